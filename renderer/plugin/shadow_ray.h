#pragma once
// Shadow rays: from a surface hit to the point a light sample names, to test whether anything lies between.
#include <cmath>

#include "renderer/core/ray.h"
#include "renderer/plugin/light.h"
#include "renderer/plugin/surface_hit.h"

namespace isotrace {

// How far short of the light's point a shadow ray stops, as a fraction of its length: the light's own surface at
// that point must not count as blocking it.
inline constexpr float kShadowRayMargin = 1e-4f;

struct ShadowSegment {
    Vec3f direction;  // unit
    float t_far;
};

// The shadow ray from `origin` (`position` pushed off its surface, SurfaceHit::spawn_origin) to the point at the
// finite `distance` along the unit `direction` from `position`. It aims at that point from `origin` itself: the
// push shortens the way to a light's plane by push / cos, more than the margin where the ray meets that plane at a
// grazing angle, so a ray that kept `direction` would reach the emitter's own surface (docs/decisions.md).
inline ShadowSegment shadow_segment(const Vec3f& position, const Vec3f& origin, const Vec3f& direction, float distance) {
    // The point less the origin, without going through the point's coordinates (they would round to their ulp).
    const Vec3f to_point = direction * distance - (origin - position);
    const float length_to_point = length(to_point);
    return {to_point * (1.0f / length_to_point), length_to_point * (1 - kShadowRayMargin)};
}

// What lies at a light sample's point: the surface of an emitter, or nothing (a point or spot light).
enum class LightPoint { OnASurface, Bare };

// The shadow ray from `hit` towards the light point `distance` along the unit `direction` (a LightSample's); lights
// at infinity (infinite distance) keep the direction and test all the way. A bare point has no plane to miss: the ray
// keeps the direction too and ends, short by the margin, where it passes closest to the point (beside it by at most
// the push off the surface), without the square root and division of aiming at it.
inline Ray shadow_ray(const SurfaceHit& hit, const Vec3f& direction, float distance, LightPoint point) {
    const Vec3f origin = hit.spawn_origin(direction);
    if (std::isinf(distance)) return {origin, direction, 0, distance};
    if (point == LightPoint::Bare) {
        const float closest = distance - dot(direction, origin - hit.position);
        return {origin, direction, 0, closest * (1 - kShadowRayMargin)};
    }
    const ShadowSegment segment = shadow_segment(hit.position, origin, direction, distance);
    return {origin, segment.direction, 0, segment.t_far};
}

// The shadow ray of a light sample: a delta light's point (a point or spot light) is bare.
inline Ray shadow_ray(const SurfaceHit& hit, const LightSample& light) {
    return shadow_ray(hit, light.direction, light.distance, light.is_delta ? LightPoint::Bare : LightPoint::OnASurface);
}

}  // namespace isotrace
