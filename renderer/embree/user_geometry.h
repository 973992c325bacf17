#pragma once
// Shared plumbing for Embree user-geometry callbacks (the analytic and implicit primitives): reading rays of a
// ray packet in double, storing conservatively rounded bounds, and recording a hit.
#include <embree3/rtcore.h>

#include <cmath>
#include <limits>

#include "renderer/math/vec3.h"

namespace isotrace::user_geometry {

inline Vec3d ray_origin(RTCRayN* rays, unsigned n, unsigned i) {
    return {RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i)};
}

inline Vec3d ray_direction(RTCRayN* rays, unsigned n, unsigned i) {
    return {RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i)};
}

// Rounds outwards, so the float box still contains the double-precision primitive.
inline void store_bounds(RTCBounds* out, const Vec3d& lower, const Vec3d& upper) {
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    out->lower_x = std::nextafter(float(lower.x), -kInfinity);
    out->lower_y = std::nextafter(float(lower.y), -kInfinity);
    out->lower_z = std::nextafter(float(lower.z), -kInfinity);
    out->upper_x = std::nextafter(float(upper.x), kInfinity);
    out->upper_y = std::nextafter(float(upper.y), kInfinity);
    out->upper_z = std::nextafter(float(upper.z), kInfinity);
}

// A committed user geometry of `primitive_count` primitives whose callbacks find their shape in
// args->geometryUserPtr (the bounds callback's own userPtr is ignored by Embree 3.13.5).
inline RTCGeometry create(RTCDevice device, void* shape, unsigned primitive_count, RTCBoundsFunction bounds,
                          RTCIntersectFunctionN intersect, RTCOccludedFunctionN occluded) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, primitive_count);
    rtcSetGeometryUserData(geometry, shape);
    rtcSetGeometryBoundsFunction(geometry, bounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, intersect);
    rtcSetGeometryOccludedFunction(geometry, occluded);
    rtcCommitGeometry(geometry);
    return geometry;
}

// Accepts a hit at distance t (the caller checked t_near < t < t_far) with geometric normal `normal`.
inline void store_hit(const RTCIntersectFunctionNArguments* args, unsigned i, float t, const Vec3d& normal) {
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
    RTCRayN_tfar(rays, args->N, i) = t;
    RTCHitN_Ng_x(hits, args->N, i) = float(normal.x);
    RTCHitN_Ng_y(hits, args->N, i) = float(normal.y);
    RTCHitN_Ng_z(hits, args->N, i) = float(normal.z);
    RTCHitN_u(hits, args->N, i) = 0;
    RTCHitN_v(hits, args->N, i) = 0;
    RTCHitN_primID(hits, args->N, i) = args->primID;
    RTCHitN_geomID(hits, args->N, i) = args->geomID;
    RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
}

}  // namespace isotrace::user_geometry
