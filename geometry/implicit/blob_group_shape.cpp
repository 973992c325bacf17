#include "geometry/implicit/blob_group_shape.h"

#include <cmath>
#include <limits>

#include "renderer/core/render_counters.h"
#include "renderer/embree/user_geometry.h"

namespace isotrace {

using user_geometry::ray_direction;
using user_geometry::ray_origin;

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

RTCGeometry BlobGroupShape::create_geometry(RTCDevice device) {
    counter_slot_ = counters::geometry_type_slot(type_name(), true);
    pieces_slot_ = counters::named_counter_slot("blobs.pieces");
    solves_slot_ = counters::named_counter_slot("blobs.polynomial_solves");
    searches_slot_ = counters::named_counter_slot("blobs.lipschitz_searches");
    roots_slot_ = counters::named_counter_slot("blobs.roots");
    return user_geometry::create(device, this, unsigned(group_.elements().size()), bounds_callback,
                                 intersect_callback, occluded_callback);
}

void BlobGroupShape::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const BlobGroupShape*>(args->geometryUserPtr);
    const WorldBounds support = self->group_.elements()[args->primID].support_bounds();
    user_geometry::store_bounds(args->bounds_o, support.lower, support.upper);
}

void BlobGroupShape::intersect_callback(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const BlobGroupShape*>(args->geometryUserPtr);
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        counters::count_test(self->counter_slot_);
        const Vec3d origin = ray_origin(rays, args->N, i), direction = ray_direction(rays, args->N, i);
        float& t_far = RTCRayN_tfar(rays, args->N, i);
        BlobQueryWork work;
        const auto t = self->group_.first_crossing(args->primID, origin, direction, RTCRayN_tnear(rays, args->N, i),
                                                   t_far, work);
        counters::add_to_named(self->pieces_slot_, work.pieces);
        counters::add_to_named(self->solves_slot_, work.polynomial_solves);
        counters::add_to_named(self->searches_slot_, work.lipschitz_searches);
        counters::add_to_named(self->roots_slot_, work.roots);
        if (!t || !(float(*t) < t_far)) continue;
        counters::count_candidate_hit(self->counter_slot_);
        user_geometry::store_hit(args, i, float(*t), self->group_.normal(args->primID, origin + direction * *t));
    }
}

void BlobGroupShape::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const BlobGroupShape*>(args->geometryUserPtr);
    RTCRayN* rays = args->ray;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        counters::count_test(self->counter_slot_);
        float& t_far = RTCRayN_tfar(rays, args->N, i);
        BlobQueryWork work;
        const auto t = self->group_.first_crossing(args->primID, ray_origin(rays, args->N, i),
                                                   ray_direction(rays, args->N, i), RTCRayN_tnear(rays, args->N, i),
                                                   t_far, work);
        counters::add_to_named(self->pieces_slot_, work.pieces);
        if (!t) continue;
        counters::count_candidate_hit(self->counter_slot_);
        t_far = -std::numeric_limits<float>::infinity();
    }
}

}  // namespace isotrace
