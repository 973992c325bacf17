#include "geometry/superquadric/superquadric_shape.h"

#include <algorithm>
#include <array>
#include <span>

#include "geometry/csg/inside_span_list.h"
#include "geometry/csg/span_combination.h"
#include "renderer/core/render_counters.h"
#include "renderer/embree/user_geometry.h"

namespace isotrace {
namespace {

// The buffers of an inside-span query: one superquadric's crossings, its spans, and the events of their union.
struct SpanBuffers {
    std::vector<Crossing> found;
    std::vector<InsideSpan> own;
    std::vector<SpanEvent> events;
};

}  // namespace

SuperquadricShape::SuperquadricShape(std::vector<Superquadric> superquadrics)
    : superquadrics_(std::move(superquadrics)),
      // Named here, not with the Embree geometry: a CSG operand records its work without one.
      work_slots_{counters::named_counter_slot("superquadric.interval_bounds"),
                  counters::named_counter_slot("superquadric.slope_bounds"),
                  counters::named_counter_slot("superquadric.slope_proofs"),
                  counters::named_counter_slot("superquadric.evaluations"),
                  counters::named_counter_slot("superquadric.halvings"),
                  counters::named_counter_slot("superquadric.refined_crossings"),
                  counters::named_counter_slot("superquadric.quadratic_solves")} {
    measure_field_step();
}

void SuperquadricShape::measure_field_step() {
    IntervalBox box = superquadrics_.empty() ? IntervalBox::point({0, 0, 0}) : superquadrics_[0].bounds();
    for (const Superquadric& s : superquadrics_) {
        const IntervalBox bounds = s.bounds();
        box.extend(bounds.lower());
        box.extend(bounds.upper());
    }
    field_step_ = 1e-6 * std::max({box.x.width(), box.y.width(), box.z.width(), 1e-300});
}

const Superquadric& SuperquadricShape::deepest(const Vec3d& point) const {
    std::size_t best = 0;
    double best_value = superquadrics_[0].continued_field(point);
    for (std::size_t i = 1; i < superquadrics_.size(); ++i) {
        const double v = superquadrics_[i].continued_field(point);
        if (v < best_value) {
            best = i;
            best_value = v;
        }
    }
    return superquadrics_[best];
}

std::optional<double> SuperquadricShape::field_value(const Vec3d& point) const {
    return -deepest(point).continued_field(point);
}

Vec3d SuperquadricShape::field_gradient(const Vec3d& point) const {
    const Superquadric& s = deepest(point);
    const Vec3d n = s.normal(point);
    if (!is_finite(n)) return {};
    const double h = field_step_;
    return n * -((s.continued_field(point + n * h) - s.continued_field(point - n * h)) / (2 * h));
}

std::size_t SuperquadricShape::memory_bytes() const {
    std::size_t bytes = superquadrics_.capacity() * sizeof(Superquadric);
    for (const Superquadric& s : superquadrics_) bytes += s.deformation().heap_bytes() + s.shape().table_bytes();
    return bytes;
}

Bounds3f SuperquadricShape::bounds() const {
    Bounds3f b;
    for (const Superquadric& s : superquadrics_) {
        const IntervalBox box = s.bounds();
        b.extend(Vec3f(box.lower()));
        b.extend(Vec3f(box.upper()));
    }
    return b;
}

void SuperquadricShape::bake(const Transform& to_world) {
    if (to_world.is_identity()) return;
    for (Superquadric& s : superquadrics_) s.transform(to_world);
    measure_field_step();
}

RTCGeometry SuperquadricShape::create_geometry(RTCDevice device) {
    counter_slot_ = counters::geometry_type_slot(type_name(), true);
    return user_geometry::create<bounds_callback>(device, this, unsigned(superquadrics_.size()), intersect_callback,
                                                  occluded_callback);
}

void SuperquadricShape::record_work(const SuperquadricWork& work) const {
    const std::array<std::uint64_t, 7> amounts{
        work.search.interval_bounds, work.search.slope_bounds, work.search.slope_proofs, work.point_values,
        work.search.halvings,        work.search.crossings,    work.quadratic_solves};
    // Most queries of a scene of many shapes pass beside a shape's quadrics and count nothing.
    if (std::none_of(amounts.begin(), amounts.end(), [](std::uint64_t amount) { return amount != 0; })) return;
    counters::add_to_named(work_slots_, amounts);
}

void SuperquadricShape::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const SuperquadricShape*>(args->geometryUserPtr);
    const IntervalBox box = self->superquadrics_[args->primID].bounds();
    user_geometry::store_bounds(args->bounds_o, box.lower(), box.upper());
}

std::optional<double> SuperquadricShape::first_hit(std::uint32_t index, const Vec3d& origin, const Vec3d& direction,
                                                   double t_near, float t_far) const {
    SuperquadricWork work;
    const auto t = superquadrics_[index].first_crossing(origin, direction, t_near, t_far, work);
    record_work(work);
    if (!t || !(*t > t_near) || !(float(*t) < t_far)) return std::nullopt;
    return t;
}

void SuperquadricShape::intersect_callback(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const SuperquadricShape*>(args->geometryUserPtr);
    user_geometry::intersect_rays(
        args, self->counter_slot_,
        [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
            return self->first_hit(args->primID, origin, direction, t_near, t_far);
        },
        [&](unsigned i, const Vec3d& origin, const Vec3d& direction, double t) {
            const Superquadric& s = self->superquadrics_[args->primID];
            user_geometry::store_hit(args, i, float(t), s.normal(origin + direction * t));
        });
}

bool SuperquadricShape::blocks(const void* self, std::uint32_t index, const Vec3d& origin, const Vec3d& direction,
                               double t_near, float t_far) {
    const auto* shape = static_cast<const SuperquadricShape*>(self);
    SuperquadricWork work;
    const bool blocked = shape->superquadrics_[index].blocks(origin, direction, t_near, t_far, work);
    shape->record_work(work);
    return blocked;
}

void SuperquadricShape::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const SuperquadricShape*>(args->geometryUserPtr);
    const Superquadric& s = self->superquadrics_[args->primID];
    user_geometry::occlude_rays(
        args, self->counter_slot_,
        [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
            return blocks(self, args->primID, origin, direction, t_near, t_far);
        },
        [&](const Vec3d& origin, const Vec3d& direction, double t_near) {
            return s.starts_within_deformed_box(origin, direction, t_near);
        },
        blocks);
}

void SuperquadricShape::primitive_spans(std::uint32_t index, const Vec3d& origin, const Vec3d& direction,
                                        double t_min, double t_max, std::vector<InsideSpan>& spans,
                                        std::vector<Crossing>& found) const {
    const Superquadric& s = superquadrics_[index];
    found.clear();
    SuperquadricWork work;
    s.crossings(origin, direction, t_min, t_max, found, work);
    record_work(work);
    append_spans_from_crossings(
        std::span<const Crossing>(found), s.contains(origin + direction * t_min), t_min, t_max,
        [&](const Crossing& c) { return BoundaryPoint{.t = c.t, .primitive = index}; }, spans);
}

void SuperquadricShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                     std::vector<InsideSpan>& spans, QueryScratch& scratch) const {
    const QueryScratch::Level level(scratch);
    auto& [found, own, events] = level.get<SpanBuffers>();
    if (superquadrics_.size() == 1) {
        primitive_spans(0, origin, direction, t_min, t_max, spans, found);
        return;
    }
    // The union of the superquadrics' spans, by the sweep that combines CSG operands.
    events.clear();
    for (std::uint32_t i = 0; i < superquadrics_.size(); ++i) {
        own.clear();
        primitive_spans(i, origin, direction, t_min, t_max, own, found);
        append_span_events(i, 0, own, events);
    }
    combine_span_events(CsgOperation::Union, std::uint32_t(superquadrics_.size()), events, spans);
}

LeadingSpan SuperquadricShape::leading_span(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                            QueryScratch&) const {
    // How far past the entry the span is shown to reach, relative to the entry's t: a hundred times the relative
    // tolerance within which CSG takes surfaces to coincide, more than any combination asks of a leading span.
    constexpr double kReach = 1e-7;
    if (superquadrics_.size() != 1 || !(t_min < t_max)) return {};
    const Superquadric& s = superquadrics_[0];
    if (s.contains(origin + direction * t_min)) return {};  // a span cut at t_min: the listing's
    SuperquadricWork work;
    const std::optional<Crossing> first = s.first_of_crossings(origin, direction, t_min, t_max, work);
    record_work(work);
    if (!first) return {LeadingSpan::Outcome::None, {}};
    const double past = first->t + kReach * std::abs(first->t);
    if (!first->entering || !(past > first->t && past < t_max) ||
        !s.inside_after_entry(origin, direction, first->t, past))
        return {};
    const BoundaryPoint enter{.t = first->t, .primitive = 0}, reached{.t = past, .primitive = BoundaryPoint::kCut};
    return {LeadingSpan::Outcome::Found, {enter, reached}};
}

Vec3d SuperquadricShape::boundary_normal(const Vec3d& origin, const Vec3d& direction, const BoundaryPoint& end) const {
    return superquadrics_[end.primitive].normal(origin + direction * end.t);
}

bool SuperquadricShape::certainly_outside(const Vec3d& point, double distance) const {
    return std::all_of(superquadrics_.begin(), superquadrics_.end(),
                       [&](const Superquadric& s) { return s.certainly_outside(point, distance); });
}

}  // namespace isotrace
