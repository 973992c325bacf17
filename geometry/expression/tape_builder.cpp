#include "geometry/expression/tape_builder.h"

#include <cmath>
#include <utility>

#include "geometry/expression/expression_evaluator.h"
#include "geometry/expression/expression_lexer.h"

namespace isotrace {
namespace {

bool commutes(Op op) { return op == Op::Add || op == Op::Mul || op == Op::Min || op == Op::Max; }

// Whether IEEE arithmetic without the domain rules would leave the reals here (the rules then decide the value).
const char* domain_problem(Op op, double a, double b) {
    switch (op) {
        case Op::Div: return b == 0 ? "division by zero" : nullptr;
        case Op::Sqrt: return a < 0 ? "the square root of a negative number" : nullptr;
        case Op::Log: return a <= 0 ? "the logarithm of a number that is not positive" : nullptr;
        default: return nullptr;
    }
}

}  // namespace

int operand_count(Op op) {
    switch (op) {
        case Op::Constant:
        case Op::X:
        case Op::Y:
        case Op::Z: return 0;
        case Op::Add:
        case Op::Sub:
        case Op::Mul:
        case Op::Div:
        case Op::Atan2:
        case Op::Min:
        case Op::Max: return 2;
        case Op::Noise:
        case Op::Field: return 3;
        default: return 1;
    }
}

std::optional<double> TapeBuilder::constant_value(int slot) const {
    if (!is_constant_[static_cast<std::size_t>(slot)]) return std::nullopt;
    return tape_.code[static_cast<std::size_t>(slot)].constant;
}

int TapeBuilder::constant(double value) { return emit({Op::Constant, 0, 0, 0, 0, value}, 0); }

int TapeBuilder::emit(const Instruction& given, std::size_t offset) {
    Instruction in = given;
    const int operands = operand_count(in.op);
    if (operands < 3) in.c = 0;
    if (operands < 2) in.b = 0;
    if (operands < 1) in.a = 0;
    if (commutes(in.op) && in.b < in.a) std::swap(in.a, in.b);

    const int slots[] = {in.a, in.b, in.c};
    bool all_constant = operands > 0 && in.op != Op::Field;
    for (int k = 0; k < operands; ++k) all_constant = all_constant && is_constant_[static_cast<std::size_t>(slots[k])];
    if (all_constant) {
        // The instruction on its operands' values alone, moved to slots 0 to 2.
        double values[3] = {};
        for (int k = 0; k < operands; ++k) values[k] = tape_.code[static_cast<std::size_t>(slots[k])].constant;
        Instruction local = in;
        local.a = 0, local.b = 1, local.c = 2;
        // Settled: an overflow has stopped at the largest double.
        const double value = expression_math::apply(tape_, local, values, 0.0, 0.0, 0.0);
        if (check_constants_) {
            if (const char* problem = domain_problem(in.op, values[0], values[1]))
                throw ExpressionError{offset, std::string("a constant part of the expression is not a number: ") + problem};
            if (std::abs(value) >= expression_math::kLargest)
                throw ExpressionError{offset, "a constant part of the expression overflows"};
        }
        return constant(value);
    }

    // x + 0, x − 0, x·1 and x/1 are x (vector arithmetic makes many: p - vec(0, 0.35, 0)).
    if (operands == 2) {
        const std::optional<double> left = constant_value(in.a), right = constant_value(in.b);
        const auto is = [](const std::optional<double>& c, double v) { return c && *c == v; };
        if (((in.op == Op::Add || in.op == Op::Sub) && is(right, 0)) || ((in.op == Op::Mul || in.op == Op::Div) && is(right, 1)))
            return in.a;
        if ((in.op == Op::Add && is(left, 0)) || (in.op == Op::Mul && is(left, 1))) return in.b;
    }

    const Key key{in.op, in.a, in.b, in.c, in.index, in.constant};
    if (const auto found = slots_.find(key); found != slots_.end()) return found->second;
    const int slot = static_cast<int>(tape_.code.size());
    tape_.code.push_back(in);
    is_constant_.push_back(in.op == Op::Constant);
    slots_.emplace(key, slot);
    return slot;
}

int TapeBuilder::add_noise(const NoiseTerm& term) {
    // The same noise twice is one term, so that its calls are common subexpressions.
    const auto same = [&term](const NoiseTerm& t) {
        const FractalOctaves &a = t.fractal, &b = term.fractal;
        return t.kind == term.kind && a.count() == b.count() && a.lacunarity() == b.lacunarity() &&
               a.gain() == b.gain() && a.settings().seed == b.settings().seed && t.jitter == term.jitter;
    };
    for (std::size_t i = 0; i < tape_.noises.size(); ++i)
        if (same(tape_.noises[i])) return static_cast<int>(i);
    tape_.noises.push_back(term);
    return static_cast<int>(tape_.noises.size()) - 1;
}

int TapeBuilder::add_field(std::shared_ptr<const ImplicitField> field) {
    tape_.fields.push_back(std::move(field));
    return static_cast<int>(tape_.fields.size()) - 1;
}

ExpressionTape TapeBuilder::finish(int output) const {
    std::vector<bool> live(tape_.code.size(), false);
    live[static_cast<std::size_t>(output)] = true;
    for (int i = output; i >= 0; --i) {
        if (!live[i]) continue;
        const Instruction& in = tape_.code[i];
        const int slots[] = {in.a, in.b, in.c};
        for (int k = 0; k < operand_count(in.op); ++k) live[slots[k]] = true;
    }
    // The sine and the cosine of one slot, both live, are written side by side as a SinCos pair: an evaluator
    // computes them together (one range reduction, and a derivative needs both anyway).
    std::map<std::pair<Op, int>, int> trig;  // (Sin or Cos, operand) -> instruction
    for (int i = 0; i <= output; ++i)
        if (live[i] && (tape_.code[i].op == Op::Sin || tape_.code[i].op == Op::Cos))
            trig[{tape_.code[i].op, tape_.code[i].a}] = i;
    ExpressionTape tape;
    tape.noises = tape_.noises;
    tape.fields = tape_.fields;
    std::vector<int> renumbered(tape_.code.size(), -1);
    const auto append = [&](int i, Op op) {
        Instruction in = tape_.code[i];
        in.op = op;
        int* operands[] = {&in.a, &in.b, &in.c};
        for (int k = 0; k < operand_count(in.op); ++k) *operands[k] = renumbered[*operands[k]];
        renumbered[i] = static_cast<int>(tape.code.size());
        tape.code.push_back(in);
    };
    // Constants first, so that an evaluator writes them in one tight loop.
    for (int i = 0; i <= output; ++i)
        if (live[i] && tape_.code[i].op == Op::Constant) append(i, Op::Constant);
    tape.constants = tape.code.size();
    for (int i = 0; i <= output; ++i) {
        if (!live[i] || renumbered[i] >= 0) continue;
        const Instruction& in = tape_.code[i];
        if (in.op == Op::Sin || in.op == Op::Cos) {
            const auto sine = trig.find({Op::Sin, in.a}), cosine = trig.find({Op::Cos, in.a});
            if (sine != trig.end() && cosine != trig.end()) {
                append(sine->second, Op::SinCos);
                append(cosine->second, Op::Cos);
                continue;
            }
        }
        append(i, in.op);
    }
    return tape;
}

}  // namespace isotrace
