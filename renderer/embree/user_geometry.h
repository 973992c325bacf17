#pragma once
// Shared plumbing for Embree user-geometry callbacks (the analytic and implicit primitives): reading rays of a
// ray packet in double, storing conservatively rounded bounds, and recording a hit.
#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "renderer/core/render_counters.h"
#include "renderer/core/thread_sanitizer.h"
#include "renderer/embree/query_context.h"
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

// Embree calls bounds callbacks in its own TBB tasks while it builds the BVH, a hand-off ThreadSanitizer cannot see
// (Embree and TBB are not instrumented): every call first acquires the shape, which create() published.
template <RTCBoundsFunction bounds>
void announced_bounds(const RTCBoundsFunctionArguments* args) {
    thread_sanitizer::acquire(args->geometryUserPtr);
    bounds(args);
}

// A committed user geometry of `primitive_count` primitives whose callbacks find their shape in
// args->geometryUserPtr (the bounds callback's own userPtr is ignored by Embree 3.13.5). The shape must be
// complete: its bounds may be computed on other threads from here on.
template <RTCBoundsFunction bounds>
RTCGeometry create(RTCDevice device, void* shape, unsigned primitive_count, RTCIntersectFunctionN intersect,
                   RTCOccludedFunctionN occluded) {
    thread_sanitizer::publish(shape);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, primitive_count);
    rtcSetGeometryUserData(geometry, shape);
    rtcSetGeometryBoundsFunction(geometry, announced_bounds<bounds>, nullptr);
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

// The loop of an intersect callback: for every active ray i of the packet, count an intersection test and ask
// first_hit(origin, direction, t_near, t_far) for the primitive's hit distance (std::optional<double>, already
// checked against the ray's interval as the shape needs); for a hit, count a candidate and call
// record(i, origin, direction, t), which stores it (store_hit).
template <class FirstHit, class Record>
void intersect_rays(const RTCIntersectFunctionNArguments* args, int counter_slot, FirstHit&& first_hit,
                    Record&& record) {
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        counters::count_test(counter_slot);
        const Vec3d origin = ray_origin(rays, args->N, i), direction = ray_direction(rays, args->N, i);
        const std::optional<double> t =
            first_hit(origin, direction, double(RTCRayN_tnear(rays, args->N, i)), RTCRayN_tfar(rays, args->N, i));
        if (!t) continue;
        counters::count_candidate_hit(counter_slot);
        record(i, origin, direction, *t);
    }
}

// The loop of an occluded callback, with first_hit as above: a hit occludes the ray (t_far = −∞). A query for
// which puts_off(origin, direction, t_near) is true is put off to the second pass of a two-pass occlusion query
// (OcclusionPass), where ask_later(shape, primitive, ...) answers it as first_hit would; the other queries are
// answered in the first pass or in a single one.
template <class FirstHit, class PutsOff>
void occlude_rays(const RTCOccludedFunctionNArguments* args, int counter_slot, FirstHit&& first_hit,
                  PutsOff&& puts_off, PutOffQuery::Ask ask_later) {
    QueryContext& query = query_context(args->context);
    RTCRayN* rays = args->ray;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const Vec3d origin = ray_origin(rays, args->N, i), direction = ray_direction(rays, args->N, i);
        const double t_near = RTCRayN_tnear(rays, args->N, i);
        float& t_far = RTCRayN_tfar(rays, args->N, i);
        if (query.occlusion_pass != OcclusionPass::All) {
            const bool put_off = puts_off(origin, direction, t_near);
            if (put_off != (query.occlusion_pass == OcclusionPass::AtStarts)) {
                if (put_off)
                    query.put_off.add({ask_later, args->geometryUserPtr, args->primID, counter_slot, i,
                                       {origin.x, origin.y, origin.z}, {direction.x, direction.y, direction.z},
                                       t_near, t_far},
                                      ask_later && rays == query.rays && args->N == query.ray_count);
                continue;
            }
        }
        counters::count_test(counter_slot);
        if (!first_hit(origin, direction, t_near, t_far)) continue;
        counters::count_candidate_hit(counter_slot);
        t_far = -std::numeric_limits<float>::infinity();
    }
}

// The same for a primitive that answers every query at once.
template <class FirstHit>
void occlude_rays(const RTCOccludedFunctionNArguments* args, int counter_slot, FirstHit&& first_hit) {
    occlude_rays(
        args, counter_slot, std::forward<FirstHit>(first_hit), [](const Vec3d&, const Vec3d&, double) { return false; },
        nullptr);
}

}  // namespace isotrace::user_geometry
