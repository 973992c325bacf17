#include "geometry/csg/solid_user_geometry.h"

#include <limits>
#include <vector>

#include "geometry/csg/inside_span_list.h"
#include "renderer/core/render_counters.h"
#include "renderer/embree/user_geometry.h"

namespace isotrace {
namespace {

// The first surface point of `solid` on the segment (t_near, t_far) of ray `i`.
std::optional<BoundaryPoint> first_crossing(const Solid& solid, RTCRayN* rays, unsigned n, unsigned i) {
    const double t_near = RTCRayN_tnear(rays, n, i), t_far = RTCRayN_tfar(rays, n, i);
    if (!(t_near < t_far)) return std::nullopt;
    thread_local std::vector<InsideSpan> spans;  // reused: no allocation per ray once warm
    spans.clear();
    solid.inside_spans(user_geometry::ray_origin(rays, n, i), user_geometry::ray_direction(rays, n, i), t_near, t_far,
                       spans);
    return first_surface_crossing(spans, t_near, t_far);
}

}  // namespace

RTCGeometry SolidUserGeometry::create(RTCDevice device, const Solid& solid, int counter_slot, const Bounds3f& bounds) {
    solid_ = &solid;
    counter_slot_ = counter_slot;
    bounds_ = bounds;
    return user_geometry::create(device, this, bounds.empty() ? 0 : 1, bounds_callback, intersect_callback,
                                 occluded_callback);
}

void SolidUserGeometry::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const SolidUserGeometry*>(args->geometryUserPtr);
    user_geometry::store_bounds(args->bounds_o, Vec3d(self->bounds_.lower), Vec3d(self->bounds_.upper));
}

void SolidUserGeometry::intersect_callback(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const SolidUserGeometry*>(args->geometryUserPtr);
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        counters::count_test(self->counter_slot_);
        const auto hit = first_crossing(*self->solid_, rays, args->N, i);
        if (!hit) continue;
        counters::count_candidate_hit(self->counter_slot_);
        user_geometry::store_hit(args, i, float(hit->t), hit->normal);
        RTCHitN_primID(RTCRayHitN_HitN(args->rayhit, args->N), args->N, i) = hit->part;
    }
}

void SolidUserGeometry::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const SolidUserGeometry*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        counters::count_test(self->counter_slot_);
        if (!first_crossing(*self->solid_, args->ray, args->N, i)) continue;
        counters::count_candidate_hit(self->counter_slot_);
        RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();
    }
}

}  // namespace isotrace
