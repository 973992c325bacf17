#include "geometry/csg/solid_user_geometry.h"

#include <limits>
#include <vector>

#include "geometry/csg/inside_span_list.h"
#include "renderer/core/render_counters.h"
#include "renderer/embree/query_context.h"
#include "renderer/embree/user_geometry.h"

namespace isotrace {
namespace {

// The first surface point of `solid` on the segment (t_near, t_far) of the ray o + t·d.
std::optional<BoundaryPoint> first_crossing(const Solid& solid, const Vec3d& origin, const Vec3d& direction,
                                            double t_near, double t_far, QueryScratch& scratch) {
    if (!(t_near < t_far)) return std::nullopt;
    const QueryScratch::Level level(scratch);
    auto& spans = level.get<std::vector<InsideSpan>>();
    spans.clear();
    solid.inside_spans(origin, direction, t_near, t_far, spans, scratch);
    return first_surface_crossing(spans, t_near, t_far);
}

}  // namespace

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
            found = first_crossing(*self->solid_, origin, direction, t_near, t_far, scratch);
            if (!found) return std::nullopt;
            return found->t;
        },
        [&](unsigned i, const Vec3d&, const Vec3d&, double t) {
            user_geometry::store_hit(args, i, float(t), found->normal);
            RTCHitN_primID(RTCRayHitN_HitN(args->rayhit, args->N), args->N, i) = found->part;
        });
}

void SolidUserGeometry::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const SolidUserGeometry*>(args->geometryUserPtr);
    QueryScratch& scratch = query_scratch(args->context);
    user_geometry::occlude_rays(args, self->counter_slot_,
                                [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
                                    return first_crossing(*self->solid_, origin, direction, t_near, t_far, scratch)
                                        .has_value();
                                });
}

}  // namespace isotrace
