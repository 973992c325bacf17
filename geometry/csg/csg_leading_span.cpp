// A union's first span without listing every operand's spans. The operands are asked (for their own leading span
// where they can tell one, else for their spans) in the order the ray enters their bounds; once the front span found
// so far begins from outside, is longer than the coincidence tolerance, and every other operand (asked, or not
// reached yet) begins beyond that tolerance after its entry, the sweep of span_combination.cpp would meet that entry
// alone and open the union's first span with it, bit for bit. That span lasts at least as long as the operand's own,
// whose exit is the lower bound leading_span promises.
#include <algorithm>
#include <limits>

#include "geometry/csg/csg_shape.h"
#include "renderer/math/line_box_clip.h"

namespace isotrace {

LeadingSpan CsgShape::leading_span(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                   QueryScratch& scratch) const {
    if (operation_ != CsgOperation::Union || !exact_boundaries_ || !(t_min < t_max)) return {};
    const QueryScratch::Level level(scratch);
    Buffers& buffers = level.get<Buffers>();
    buffers.reached.clear();
    Asked& asked = buffers.asked;
    asked = {this, origin, direction, t_min, t_max, std::move(asked.kept), std::move(asked.spans)};
    asked.kept.assign(operands_.size(), false);
    asked.spans.resize(operands_.size());
    for (std::uint32_t i = 0; i < operands_.size(); ++i) {
        const Operand& operand = operands_[i];
        if (operand.reach_lower.x > operand.reach_upper.x) continue;
        if (const auto clip = clip_line_to_box(operand.reach_lower, operand.reach_upper, origin, direction, t_min, t_max))
            buffers.reached.push_back({clip->t_enter, i});
    }
    std::sort(buffers.reached.begin(), buffers.reached.end());
    std::optional<InsideSpan> front;  // the earliest front span of the operands asked
    double others_begin = std::numeric_limits<double>::infinity();  // where the other operands asked begin
    const auto clear_of_front = [&](double t) { return t - front->enter.t > coincidence_tolerance(front->enter); };
    for (const auto& [t_reached, index] : buffers.reached) {
        if (front && clear_of_front(t_reached)) break;  // this operand and the later ones begin beyond the front's entry
        const Operand& operand = operands_[index];
        // The operand's own leading span where it can tell one (its exit may fall short of the span's: only the
        // entry and a lower bound of the exit are used here), else its spans, kept for a listing that follows.
        const LeadingSpan lead = operand_leading_span(operand, origin, direction, t_min, t_max, scratch);
        if (lead.outcome == LeadingSpan::Outcome::None) {
            asked.spans[index].clear();
            asked.kept[index] = true;
            continue;
        }
        InsideSpan span = lead.span;
        if (!lead.found()) {
            operand_spans(operand, origin, direction, t_min, t_max, buffers.operand_spans, scratch);
            asked.spans[index] = buffers.operand_spans;
            asked.kept[index] = true;
            if (buffers.operand_spans.empty()) continue;
            span = buffers.operand_spans.front();
        }
        span.enter.part += operand.first_part;
        span.exit.part += operand.first_part;
        if (front && front->enter.t <= span.enter.t) {
            others_begin = std::min(others_begin, span.enter.t);
            continue;
        }
        if (front) others_begin = std::min(others_begin, front->enter.t);
        front = span;
    }
    if (!front) return {LeadingSpan::Outcome::None, {}};  // every operand the ray reaches was asked
    if (!front->enter.on_surface() || !clear_of_front(front->exit.t) || !clear_of_front(others_begin)) return {};
    return {LeadingSpan::Outcome::Found, *front};
}

}  // namespace isotrace
