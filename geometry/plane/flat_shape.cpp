#include "geometry/plane/flat_shape.h"

#include "renderer/core/render_counters.h"
#include "renderer/embree/user_geometry.h"

namespace isotrace {

void FlatShape::bake(const Transform& to_world) {
    frame_ = frame_.transformed(to_world);
    frame_changed();
}

std::optional<double> FlatShape::first_hit(const Vec3d& origin, const Vec3d& direction, double t_near,
                                           double t_far) const {
    const std::optional<double> t = frame_.crossing(origin, direction);
    if (!t || !(*t > t_near && *t < t_far)) return std::nullopt;
    if (!covers(frame_.coordinates(origin + direction * *t))) return std::nullopt;
    return t;
}

RTCGeometry FlatShape::create_geometry(RTCDevice device) {
    counter_slot_ = counters::geometry_type_slot(type_name(), true);
    embree_bounds_ = bounds();
    return user_geometry::create<bounds_callback>(device, this, embree_bounds_.empty() ? 0 : 1, intersect_callback,
                                                  occluded_callback);
}

void FlatShape::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const FlatShape*>(args->geometryUserPtr);
    user_geometry::store_bounds(args->bounds_o, Vec3d(self->embree_bounds_.lower), Vec3d(self->embree_bounds_.upper));
}

void FlatShape::intersect_callback(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const FlatShape*>(args->geometryUserPtr);
    user_geometry::intersect_rays(
        args, self->counter_slot_,
        [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
            return self->first_hit(origin, direction, t_near, t_far);
        },
        [&](unsigned i, const Vec3d&, const Vec3d&, double t) {
            user_geometry::store_hit(args, i, float(t), self->frame_.normal());  // uv: see each shape's shading()
        });
}

void FlatShape::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const FlatShape*>(args->geometryUserPtr);
    user_geometry::occlude_rays(args, self->counter_slot_,
                                [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
                                    return self->first_hit(origin, direction, t_near, t_far).has_value();
                                });
}

}  // namespace isotrace
