// The first surface point of a CSG, and the test it rests on: a difference's result can only begin where its first
// operand begins, so when the ray enters the first operand from outside at a point that no subtracted operand can
// reach (Solid::certainly_outside, with a margin well beyond the tolerance within which CSG takes surfaces to
// coincide), that entry is the answer the full combination would give, bit for bit, without the subtracted
// operands' spans. The first operand's leading span (Solid::leading_span) is tried first, its full spans next;
// otherwise the full combination runs, reusing them. A union's first surface point is its leading span's entry.
#include <algorithm>
#include <cmath>

#include "geometry/csg/csg_shape.h"

namespace isotrace {
namespace {

// How far, in coincidence tolerances, a subtracted operand must stay from the entry for the shortcut.
constexpr double kClearance = 16;

}  // namespace

// An operand placed by a transform it kept is left alone: distances change under it.
bool CsgShape::operand_certainly_outside(const Operand& operand, const Vec3d& point, double distance) {
    return !operand.from_csg && operand.solid->certainly_outside(point, distance);
}

bool CsgShape::certainly_outside(const Vec3d& point, double distance) const {
    const auto outside = [&](const Operand& operand) { return operand_certainly_outside(operand, point, distance); };
    switch (operation_) {
        case CsgOperation::Union: return std::all_of(operands_.begin(), operands_.end(), outside);
        case CsgOperation::Intersection: return std::any_of(operands_.begin(), operands_.end(), outside);
        case CsgOperation::Difference: return outside(operands_.front());
    }
    return false;
}

std::optional<BoundaryPoint> CsgShape::first_surface_point(const Vec3d& origin, const Vec3d& direction, double t_near,
                                                           double t_far, QueryScratch& scratch) const {
    if (!(t_near < t_far)) return std::nullopt;
    const QueryScratch::Level level(scratch);
    Buffers& buffers = level.get<Buffers>();
    if (operation_ == CsgOperation::Union) {
        // The union's first span opens with its first surface point, when that lies inside the range; otherwise its
        // spans, at the level below as the leading span took them (which keeps the spans it asked for).
        const LeadingSpan lead = leading_span(origin, direction, t_near, t_far, scratch);
        if (lead.outcome == LeadingSpan::Outcome::None) return std::nullopt;
        if (lead.found() && lead.span.enter.t > t_near && lead.span.enter.t < t_far) return lead.span.enter;
        buffers.result.clear();
        inside_spans(origin, direction, t_near, t_far, buffers.result, scratch);
        return first_surface_crossing(buffers.result, t_near, t_far);
    }
    // A difference's answer when the first operand's first span (or one that ends no later) begins with an entry
    // from outside that no subtracted operand comes near.
    const bool by_entry = operation_ == CsgOperation::Difference && exact_boundaries_;
    const auto settled_entry = [&](const InsideSpan& span) -> std::optional<BoundaryPoint> {
        const BoundaryPoint& enter = span.enter;
        const double tolerance = std::max(coincidence_tolerance(enter), coincidence_tolerance(span.exit));
        // An entry from outside, into a span no shorter than the tolerance (a shorter one would be an event
        // simultaneous with its own exit).
        if (!enter.on_surface() || !(enter.t > t_near) || !(enter.t < t_far) ||
            !(span.exit.t - enter.t > kClearance * tolerance))
            return std::nullopt;
        const Vec3d point = origin + direction * enter.t;
        const double clearance = kClearance * kCoincidentRelative * (std::abs(enter.t) * length(direction) + length(point));
        const auto clear = [&](const Operand& operand) { return operand_certainly_outside(operand, point, clearance); };
        if (!std::all_of(operands_.begin() + 1, operands_.end(), clear)) return std::nullopt;
        BoundaryPoint result = enter;
        result.part += operands_.front().first_part;
        return result;
    };
    if (by_entry) {
        const LeadingSpan lead = operand_leading_span(operands_.front(), origin, direction, t_near, t_far, scratch);
        if (lead.outcome == LeadingSpan::Outcome::None) return std::nullopt;  // nothing of the first operand
        if (const std::optional<BoundaryPoint> entry = lead.found() ? settled_entry(lead.span) : std::nullopt)
            return entry;
    }
    operand_spans(operands_.front(), origin, direction, t_near, t_far, buffers.operand_spans, scratch);
    if (buffers.operand_spans.empty()) return std::nullopt;
    if (by_entry)
        if (const std::optional<BoundaryPoint> entry = settled_entry(buffers.operand_spans.front())) return entry;
    buffers.result.clear();
    combine_with_first(origin, direction, t_near, t_far, buffers.operand_spans, buffers.events, buffers.result,
                       nullptr, scratch);
    return first_surface_crossing(buffers.result, t_near, t_far);
}

}  // namespace isotrace
