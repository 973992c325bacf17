#include "geometry/csg/csg_shape.h"

#include <algorithm>
#include <array>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

#include "geometry/csg/transformed_bounds.h"
#include "renderer/core/render_counters.h"

namespace isotrace {
namespace {

Bounds3f intersect_bounds(const Bounds3f& a, const Bounds3f& b) {
    Bounds3f result;
    result.lower = max(a.lower, b.lower);
    result.upper = min(a.upper, b.upper);
    if (result.lower.x > result.upper.x || result.lower.y > result.upper.y || result.lower.z > result.upper.z)
        return {};  // the canonical empty box (Bounds3f::empty() looks at x only)
    return result;
}

// Normals of surface ends from a child's space to the CSG's (cut ends carry none, nor do ends whose normal the
// child defers: boundary_normal maps those).
void map_normals(std::span<InsideSpan> spans, const Solid& child, const Transform& to_csg) {
    for (InsideSpan& span : spans)
        for (BoundaryPoint* end : {&span.enter, &span.exit})
            if (end->on_surface() && !child.defers_normals(end->part)) end->normal = normalize(to_csg.normal(end->normal));
}

}  // namespace

CsgShape::CsgShape(CsgOperation operation, std::vector<CsgChild> children) : operation_(operation) {
    if (children.empty()) throw std::invalid_argument("a CSG needs at least one child");
    for (CsgChild& child : children) {
        Operand operand;
        operand.solid = dynamic_cast<Solid*>(child.shape.get());
        if (!operand.solid) throw std::invalid_argument("CSG child \"" + child.shape->type_name() + "\" is not a solid");
        operand.part_count = std::uint32_t(std::max<std::size_t>(1, child.shape->part_materials().size()));
        operand.first_part = part_count_;
        part_count_ += operand.part_count;
        exact_boundaries_ = exact_boundaries_ && operand.solid->exact_boundaries();
        operand.material = std::move(child.material);
        operand.shape = std::move(child.shape);
        place(operand, child.to_csg);
        operands_.push_back(std::move(operand));
    }
    span_slots_ = {counters::named_counter_slot("csg.span_combinations"),
                   counters::named_counter_slot("csg.span_events")};
}

void CsgShape::place(Operand& operand, const Transform& to_csg) {
    // A child that kept an earlier placement is still in its own space: compose, and try to bake the whole.
    const Transform placement = operand.to_csg ? to_csg * *operand.to_csg : to_csg;
    if (operand.shape->can_bake(placement)) {
        operand.shape->bake(placement);
        operand.to_csg.reset();
        operand.from_csg.reset();
    } else {
        operand.to_csg = placement;
        operand.from_csg = placement.inverse();
    }
    operand.reach_lower = {1, 1, 1};
    operand.reach_upper = {-1, -1, -1};
    const Bounds3f bounds = operand_bounds(operand);
    if (bounds.empty()) return;
    // A float's rounding is within 2⁻²⁴ of the coordinate's magnitude.
    const Vec3d lower(bounds.lower), upper(bounds.upper);
    const Vec3d margin = (abs(lower) + abs(upper)) * 1e-6;
    operand.reach_lower = lower - margin;
    operand.reach_upper = upper + margin;
}

void CsgShape::bake(const Transform& to_world) {
    for (Operand& operand : operands_) place(operand, to_world);
}

std::size_t CsgShape::memory_bytes() const {
    std::size_t bytes = operands_.capacity() * sizeof(Operand);
    for (const Operand& operand : operands_) bytes += operand.shape->memory_bytes();
    return bytes;
}

Bounds3f CsgShape::operand_bounds(const Operand& operand) const {
    const Bounds3f own = operand.shape->bounds();
    if (!operand.to_csg || own.empty()) return own;
    return transformed_bounds(Vec3d(own.lower), Vec3d(own.upper), *operand.to_csg);
}

Bounds3f CsgShape::bounds() const {
    Bounds3f result = operand_bounds(operands_.front());
    if (operation_ == CsgOperation::Difference) return result;  // nothing outside the first child survives
    for (std::size_t i = 1; i < operands_.size(); ++i) {
        const Bounds3f b = operand_bounds(operands_[i]);
        if (operation_ == CsgOperation::Intersection) {
            result = intersect_bounds(result, b);
        } else if (!b.empty()) {
            result.extend(b.lower);
            result.extend(b.upper);
        }
    }
    return result;
}

void CsgShape::prepare_span_queries(RTCDevice device) {
    for (std::size_t i = 0; i < operands_.size(); ++i) {
        // Children that keep statistics per object report under "<object>/<child index>".
        operands_[i].shape->set_object_name(object_name() + "/" + std::to_string(i));
        operands_[i].solid->prepare_span_queries(device);
    }
}

RTCGeometry CsgShape::create_geometry(RTCDevice device) {
    prepare_span_queries(device);
    return geometry_.create(device, *this, counters::geometry_type_slot(type_name(), true), bounds());
}

LocalShading CsgShape::shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d&) const {
    // primID: the part (SolidUserGeometry)
    return {.geometric_normal = geometric_normal, .normal = geometric_normal, .part = hit.primID};
}

std::vector<MaterialReference> CsgShape::part_materials() const {
    std::vector<MaterialReference> parts;
    for (const Operand& operand : operands_) {
        const std::vector<MaterialReference> inner = operand.shape->part_materials();
        if (inner.empty()) parts.push_back(operand.material);
        for (const MaterialReference& part : inner) parts.push_back(part.name.empty() ? operand.material : part);
    }
    return parts;
}

void CsgShape::operand_spans(const Operand& operand, const Vec3d& origin, const Vec3d& direction, double t_min,
                             double t_max, std::vector<InsideSpan>& spans, QueryScratch& scratch) const {
    spans.clear();
    if (operand.from_csg) {
        operand.solid->inside_spans(operand.from_csg->point(origin), operand.from_csg->vector(direction), t_min, t_max,
                                    spans, scratch);
        map_normals(spans, *operand.solid, *operand.to_csg);
    } else {
        operand.solid->inside_spans(origin, direction, t_min, t_max, spans, scratch);
    }
}

LeadingSpan CsgShape::operand_leading_span(const Operand& operand, const Vec3d& origin, const Vec3d& direction,
                                           double t_min, double t_max, QueryScratch& scratch) const {
    if (!operand.from_csg) return operand.solid->leading_span(origin, direction, t_min, t_max, scratch);
    LeadingSpan lead = operand.solid->leading_span(operand.from_csg->point(origin), operand.from_csg->vector(direction),
                                                   t_min, t_max, scratch);
    if (lead.found()) map_normals(std::span<InsideSpan>(&lead.span, 1), *operand.solid, *operand.to_csg);
    return lead;
}

std::size_t CsgShape::operand_of(std::uint32_t part) const {
    std::size_t i = 0;
    while (i + 1 < operands_.size() && part >= operands_[i + 1].first_part) ++i;
    return i;
}

bool CsgShape::defers_normals(std::uint32_t part) const {
    const Operand& operand = operands_[operand_of(part)];
    return operand.solid->defers_normals(part - operand.first_part);
}

// The child's normal, then what operand_spans and the combination do to a normal they carry: map it to the CSG's
// space, and flip it where the child is subtracted (the same operations in the same order, so the same bits).
Vec3d CsgShape::boundary_normal(const Vec3d& origin, const Vec3d& direction, const BoundaryPoint& end) const {
    const std::size_t index = operand_of(end.part);
    const Operand& operand = operands_[index];
    BoundaryPoint own = end;
    own.part -= operand.first_part;
    if (!operand.solid->defers_normals(own.part)) return end.normal;
    Vec3d normal = operand.from_csg ? operand.solid->boundary_normal(operand.from_csg->point(origin),
                                                                    operand.from_csg->vector(direction), own)
                                    : operand.solid->boundary_normal(origin, direction, own);
    if (operand.to_csg) normal = normalize(operand.to_csg->normal(normal));
    return operation_ == CsgOperation::Difference && index > 0 ? -normal : normal;
}

void CsgShape::operand_spans(std::uint32_t index, const Asked* asked, const Vec3d& origin, const Vec3d& direction,
                             double t_min, double t_max, std::vector<InsideSpan>& spans, QueryScratch& scratch) const {
    if (asked && asked->along(this, origin, direction, t_min, t_max) && asked->kept[index]) {
        spans = asked->spans[index];
        return;
    }
    operand_spans(operands_[index], origin, direction, t_min, t_max, spans, scratch);
}

void CsgShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                            std::vector<InsideSpan>& spans, QueryScratch& scratch) const {
    const QueryScratch::Level level(scratch);
    Buffers& buffers = level.get<Buffers>();
    operand_spans(0, &buffers.asked, origin, direction, t_min, t_max, buffers.operand_spans, scratch);
    combine_with_first(origin, direction, t_min, t_max, buffers.operand_spans, buffers.events, spans, &buffers.asked,
                       scratch);
}

void CsgShape::combine_with_first(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                  std::vector<InsideSpan>& operand_buffer, std::vector<SpanEvent>& events,
                                  std::vector<InsideSpan>& spans, const Asked* asked, QueryScratch& scratch) const {
    events.clear();
    const bool narrows = operation_ != CsgOperation::Union;  // the result lies within the first child's spans
    for (std::uint32_t i = 0; i < operands_.size(); ++i) {
        const Operand& operand = operands_[i];
        if (i > 0) operand_spans(i, asked, origin, direction, t_min, t_max, operand_buffer, scratch);
        const bool bounds_result = operation_ == CsgOperation::Intersection || i == 0;
        if (narrows && bounds_result) {
            if (operand_buffer.empty()) return;
            // Later children only matter where this one is inside, give or take the tolerance within which span
            // ends are simultaneous: a later child's surface that coincides with this one's end must be seen as
            // a surface there, not as a query that starts or ends exactly on it (where the side it is on is a
            // matter of rounding).
            const BoundaryPoint &enter = operand_buffer.front().enter, &exit = operand_buffer.back().exit;
            t_min = std::max(t_min, enter.t - coincidence_tolerance(enter));
            t_max = std::min(t_max, exit.t + coincidence_tolerance(exit));
        }
        append_span_events(i, operand.first_part, operand_buffer, events);
    }
    counters::add_to_named(span_slots_, std::array<std::uint64_t, 2>{1, events.size()});
    combine_span_events(operation_, std::uint32_t(operands_.size()), events, spans);
}

}  // namespace isotrace
