#include "geometry/expression/tape_pruning.h"

#include <algorithm>
#include <map>
#include <utility>

#include "geometry/expression/expression_evaluator.h"
#include "geometry/expression/tape_builder.h"

namespace isotrace {
namespace {

enum Choice : std::uint8_t { kNone = 0, kFirst = 1, kSecond = 2, kNegated = 3 };

}  // namespace

std::vector<std::uint8_t> settled_choices(const ExpressionTape& tape, const IntervalBox& box) {
    std::vector<std::uint8_t> choices(tape.code.size(), kNone);
    // A tape without a choice to settle is not run (a noise's intervals are costly).
    const auto has_choice = [](const Instruction& in) { return in.op == Op::Min || in.op == Op::Max || in.op == Op::Abs; };
    if (std::none_of(tape.code.begin(), tape.code.end(), has_choice)) return choices;
    std::vector<Interval> slots(tape.code.size());
    expression_math::run_into<Interval>(tape, box.x, box.y, box.z, slots.data());
    // a − b, where the tape has it, settles min(a, b) and max(a, b) as well (a smooth blend's |a − b| ≥ r does).
    std::map<std::pair<int, int>, int> difference;
    for (std::size_t i = 0; i < tape.code.size(); ++i)
        if (tape.code[i].op == Op::Sub) difference[{tape.code[i].a, tape.code[i].b}] = int(i);
    for (std::size_t i = 0; i < tape.code.size(); ++i) {
        const Instruction& in = tape.code[i];
        if (in.op == Op::Abs) {
            if (slots[in.a].lo >= 0) choices[i] = kFirst;
            else if (slots[in.a].hi <= 0) choices[i] = kNegated;
            continue;
        }
        if (in.op != Op::Min && in.op != Op::Max) continue;
        // Whether a ≤ b throughout, or b ≤ a throughout.
        const Interval a = slots[in.a], b = slots[in.b];
        bool a_below = a.hi <= b.lo, b_below = b.hi <= a.lo;
        if (const auto d = difference.find({in.a, in.b}); d != difference.end()) {
            a_below = a_below || slots[d->second].hi < 0;
            b_below = b_below || slots[d->second].lo > 0;
        }
        if (const auto d = difference.find({in.b, in.a}); d != difference.end()) {
            a_below = a_below || slots[d->second].lo > 0;
            b_below = b_below || slots[d->second].hi < 0;
        }
        if (a_below || b_below) choices[i] = (a_below == (in.op == Op::Min)) ? kFirst : kSecond;
    }
    return choices;
}

ExpressionTape pruned_tape(const ExpressionTape& tape, const std::vector<std::uint8_t>& choices) {
    TapeBuilder builder(false);
    for (const NoiseTerm& noise : tape.noises) builder.add_noise(noise);
    for (const auto& field : tape.fields) builder.add_field(field);
    std::vector<int> slot(tape.code.size());
    for (std::size_t i = 0; i < tape.code.size(); ++i) {
        Instruction in = tape.code[i];
        switch (choices[i]) {
            case kFirst: slot[i] = slot[in.a]; continue;
            case kSecond: slot[i] = slot[in.b]; continue;
            case kNegated: slot[i] = builder.unary(Op::Neg, slot[in.a], 0); continue;
            default: break;
        }
        if (in.op == Op::Constant) {
            slot[i] = builder.constant(in.constant);
            continue;
        }
        if (in.op == Op::SinCos) in.op = Op::Sin;  // finish() pairs it with its cosine again
        int* operands[] = {&in.a, &in.b, &in.c};
        for (int k = 0; k < operand_count(in.op); ++k) *operands[k] = slot[*operands[k]];
        slot[i] = builder.emit(in, 0);
    }
    return builder.finish(slot.back());
}

}  // namespace isotrace
