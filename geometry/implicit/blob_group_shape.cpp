#include "geometry/implicit/blob_group_shape.h"

#include <cmath>
#include <limits>
#include <optional>

#include "renderer/core/render_counters.h"
#include "renderer/embree/user_geometry.h"

namespace isotrace {

BlobGroupShape::BlobGroupShape(BlobGroup group) : group_(std::move(group)) {}

Bounds3f BlobGroupShape::bounds() const {
    Bounds3f b;
    for (const Metacube& element : group_.elements()) {
        const WorldBounds support = element.support_bounds();
        b.extend(Vec3f(support.lower));
        b.extend(Vec3f(support.upper));
    }
    return b;
}

void BlobGroupShape::register_counters() {
    counter_slot_ = counters::geometry_type_slot(type_name(), true);
    const auto slots = [](const std::string& prefix) {
        return WorkSlots{counters::named_counter_slot(prefix + ".pieces"),
                         counters::named_counter_slot(prefix + ".pieces_skipped_by_bounds"),
                         counters::named_counter_slot(prefix + ".polynomial_solves"),
                         counters::named_counter_slot(prefix + ".lipschitz_searches"),
                         counters::named_counter_slot(prefix + ".root_iterations"),
                         counters::named_counter_slot(prefix + ".roots")};
    };
    all_groups_ = slots(type_name());
    this_group_ = slots(type_name() + "[" + (object_name().empty() ? "unnamed" : object_name()) + "]");
}

void BlobGroupShape::count_work(const BlobQueryWork& work) const {
    if (work.pieces == 0 && work.roots == 0) return;  // most queries find their stretch settled already
    for (const WorkSlots& slots : {all_groups_, this_group_}) {
        counters::add_to_named(slots.pieces, work.pieces);
        counters::add_to_named(slots.skipped, work.skipped_pieces);
        counters::add_to_named(slots.solves, work.polynomial_solves);
        counters::add_to_named(slots.searches, work.lipschitz_searches);
        counters::add_to_named(slots.iterations, work.root_iterations);
        counters::add_to_named(slots.roots, work.roots);
    }
}

RTCGeometry BlobGroupShape::create_geometry(RTCDevice device) {
    register_counters();
    return user_geometry::create(device, this, unsigned(group_.elements().size()), bounds_callback,
                                 intersect_callback, occluded_callback);
}

void BlobGroupShape::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const BlobGroupShape*>(args->geometryUserPtr);
    const WorldBounds support = self->group_.elements()[args->primID].support_bounds();
    user_geometry::store_bounds(args->bounds_o, support.lower, support.upper);
}

std::optional<double> BlobGroupShape::first_hit(std::uint32_t element, const Vec3d& origin, const Vec3d& direction,
                                                double t_near, float t_far) const {
    BlobQueryWork work;
    const auto t = group_.first_crossing(element, origin, direction, t_near, t_far, work);
    count_work(work);
    return t;
}

void BlobGroupShape::intersect_callback(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const BlobGroupShape*>(args->geometryUserPtr);
    user_geometry::intersect_rays(
        args, self->counter_slot_,
        [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) -> std::optional<double> {
            const auto t = self->first_hit(args->primID, origin, direction, t_near, t_far);
            if (!t || !(float(*t) < t_far)) return std::nullopt;
            return t;
        },
        [&](unsigned i, const Vec3d& origin, const Vec3d& direction, double t) {
            user_geometry::store_hit(args, i, float(t), self->group_.normal(origin + direction * t));
        });
}

void BlobGroupShape::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const BlobGroupShape*>(args->geometryUserPtr);
    user_geometry::occlude_rays(args, self->counter_slot_,
                                [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
                                    return self->first_hit(args->primID, origin, direction, t_near, t_far);
                                });
}

void BlobGroupShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                  std::vector<InsideSpan>& spans) const {
    thread_local std::vector<FieldCrossing> crossings;
    crossings.clear();
    BlobQueryWork work;
    const int sign_at_start = group_.crossings(origin, direction, t_min, t_max, crossings, work);
    count_work(work);
    // Crossings alternate in direction (each one flips the field's sign), so spans pair entries with exits.
    std::optional<BoundaryPoint> entry;
    if (sign_at_start > 0) entry = BoundaryPoint{t_min, {0, 0, 1}, BoundaryPoint::kCut};
    for (const FieldCrossing& crossing : crossings) {
        const BoundaryPoint point{crossing.t, group_.normal(origin + direction * crossing.t),
                                  crossing.element};
        if (crossing.entering) {
            if (!entry) entry = point;
        } else if (entry) {
            spans.push_back({*entry, point});
            entry.reset();
        }
    }
    if (entry) spans.push_back({*entry, BoundaryPoint{t_max, {0, 0, 1}, BoundaryPoint::kCut}});
}

}  // namespace isotrace
