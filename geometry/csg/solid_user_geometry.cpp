#include "geometry/csg/solid_user_geometry.h"

#include "renderer/core/render_counters.h"
#include "renderer/embree/query_context.h"
#include "renderer/embree/user_geometry.h"

namespace isotrace {

RTCGeometry SolidUserGeometry::create(RTCDevice device, const Solid& solid, int counter_slot, const Bounds3f& bounds) {
    solid_ = &solid;
    counter_slot_ = counter_slot;
    bounds_ = bounds;
    return user_geometry::create<bounds_callback>(device, this, bounds.empty() ? 0 : 1, intersect_callback,
                                                  occluded_callback);
}

void SolidUserGeometry::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const SolidUserGeometry*>(args->geometryUserPtr);
    user_geometry::store_bounds(args->bounds_o, Vec3d(self->bounds_.lower), Vec3d(self->bounds_.upper));
}

void SolidUserGeometry::intersect_callback(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const SolidUserGeometry*>(args->geometryUserPtr);
    QueryScratch& scratch = query_scratch(args->context);
    std::optional<BoundaryPoint> found;  // the hit of the ray being handled
    user_geometry::intersect_rays(
        args, self->counter_slot_,
        [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) -> std::optional<double> {
            found = self->solid_->first_surface_point(origin, direction, t_near, t_far, scratch);
            if (!found) return std::nullopt;
            return found->t;
        },
        [&](unsigned i, const Vec3d& origin, const Vec3d& direction, double t) {
            user_geometry::store_hit(args, i, float(t), self->solid_->boundary_normal(origin, direction, *found));
            RTCHitN_primID(RTCRayHitN_HitN(args->rayhit, args->N), args->N, i) = found->part;
        });
}

void SolidUserGeometry::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const SolidUserGeometry*>(args->geometryUserPtr);
    QueryScratch& scratch = query_scratch(args->context);
    user_geometry::occlude_rays(args, self->counter_slot_,
                                [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
                                    return self->solid_->first_surface_point(origin, direction, t_near, t_far, scratch)
                                        .has_value();
                                });
}

}  // namespace isotrace
