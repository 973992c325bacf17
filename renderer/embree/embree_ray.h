#pragma once
// A Ray in Embree's RTCRay layout, and the test every ray passes before Embree sees it.
#include <embree3/rtcore.h>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "renderer/core/ray.h"
#include "renderer/math/lanes.h"
#include "renderer/math/lanes4.h"

namespace isotrace {

// What Embree can trace: origin and direction components at most its FLT_LARGE in magnitude (it asserts that and
// aborts the process otherwise), a non-zero direction and 0 <= t_near <= t_far, none of them NaN. Scene values
// are held within kWorldLimit (renderer/core/ray.h), below FLT_LARGE, where they are read, so a ray fails this only
// when arithmetic on valid values went wrong; RenderScene then answers without Embree (a miss, or blocked for a
// shadow ray) and counts it under "rays.untraceable". Every comparison is false for NaN.
// Written once for one ray (float: a bool) and for a packet's lanes (FloatLanes: a mask per lane).
template <class Float>
auto traceable(Float origin_x, Float origin_y, Float origin_z, Float direction_x, Float direction_y, Float direction_z,
               Float t_near, Float t_far) {
    constexpr float kLimit = 1.844E18f;  // Embree's FLT_LARGE
    // Bitwise on ints or masks (a unary + makes a bool an int), not && and ||: every traced ray passes, and without a
    // branch after each test the check takes half the instructions (each ray of the path tracer is checked).
    const auto within = [](Float value) { return +(abs(value) <= kLimit); };
    const auto inside = within(origin_x) & within(origin_y) & within(origin_z) & within(direction_x) &
                        within(direction_y) & within(direction_z);
    const auto direction_non_zero = +(direction_x != 0.0f) | +(direction_y != 0.0f) | +(direction_z != 0.0f);
    return inside & direction_non_zero & +(t_near >= 0.0f) & +(t_near <= t_far);
}

inline bool is_traceable(float origin_x, float origin_y, float origin_z, float direction_x, float direction_y,
                         float direction_z, float t_near, float t_far) {
    return traceable(origin_x, origin_y, origin_z, direction_x, direction_y, direction_z, t_near, t_far) != 0;
}

inline bool is_traceable(const Ray& ray) {
    return is_traceable(ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z,
                        ray.t_near, ray.t_far);
}

// Writes `ray` into Embree's layout in three 16-byte stores, the way Embree loads it: built field by field, the
// ray was stored as scalars and reloaded as vectors, and a load wider than the stores before it waits for them
// (a failed store forwarding, on the path tracer's hottest path: docs/decisions.md, "Hot data is written the way it
// is read").
// The caller has checked is_traceable(ray).
inline void set_embree_ray(RTCRay& r, const Ray& ray) {
    static_assert(offsetof(RTCRay, tnear) == 12 && offsetof(RTCRay, time) == 28 && offsetof(RTCRay, flags) == 44);
    const Float4 origin_and_near{ray.origin.x, ray.origin.y, ray.origin.z, ray.t_near};
    const Float4 direction_and_time{ray.direction.x, ray.direction.y, ray.direction.z, 0.0f};
    // Debian's Embree is built with ray masks on: every geometry is seen (mask all ones); id and flags 0.
    const Uint4 far_mask_id_flags{std::bit_cast<std::uint32_t>(ray.t_far), 0xFFFFFFFFu, 0, 0};
    std::memcpy(&r.org_x, &origin_and_near, sizeof origin_and_near);
    std::memcpy(&r.dir_x, &direction_and_time, sizeof direction_and_time);
    std::memcpy(&r.tfar, &far_mask_id_flags, sizeof far_mask_id_flags);
}

}  // namespace isotrace
