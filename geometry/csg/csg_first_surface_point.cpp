// The first surface point of a CSG, and the test it rests on: a difference's result can only begin where its first
// operand begins, so when the ray enters the first operand from outside at a point that no subtracted operand can
// reach (Solid::certainly_outside, with a margin well beyond the tolerance within which CSG takes surfaces to
// coincide), that entry is the answer the full combination would give, bit for bit, without the subtracted
// operands' spans. Otherwise the full combination runs, reusing the first operand's spans.
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
    operand_spans(operands_.front(), origin, direction, t_near, t_far, buffers.operand_spans, scratch);
    if (buffers.operand_spans.empty() && operation_ != CsgOperation::Union) return std::nullopt;
    if (operation_ == CsgOperation::Difference && exact_boundaries_) {
        const InsideSpan& span = buffers.operand_spans.front();
        const BoundaryPoint& enter = span.enter;
        const double tolerance = std::max(coincidence_tolerance(enter), coincidence_tolerance(span.exit));
        // An entry from outside, into a span no shorter than the tolerance (a shorter one would be an event
        // simultaneous with its own exit).
        if (enter.on_surface() && enter.t > t_near && enter.t < t_far && span.exit.t - enter.t > kClearance * tolerance) {
            const Vec3d point = origin + direction * enter.t;
            const double clearance =
                kClearance * kCoincidentRelative * (std::abs(enter.t) * length(direction) + length(point));
            const auto clear = [&](const Operand& operand) {
                return operand_certainly_outside(operand, point, clearance);
            };
            if (std::all_of(operands_.begin() + 1, operands_.end(), clear)) {
                BoundaryPoint result = enter;
                result.part += operands_.front().first_part;
                return result;
            }
        }
    }
    buffers.result.clear();
    combine_with_first(origin, direction, t_near, t_far, buffers.operand_spans, buffers.events, buffers.result, scratch);
    return first_surface_crossing(buffers.result, t_near, t_far);
}

}  // namespace isotrace
