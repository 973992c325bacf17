#pragma once
// A Ray in Embree's RTCRay layout.
#include <embree3/rtcore.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "renderer/core/ray.h"
#include "renderer/math/lanes4.h"

namespace isotrace {

// Writes `ray` into Embree's layout in three 16-byte stores, the way Embree loads it: built field by field, the
// ray was stored as scalars and reloaded as vectors, and a load wider than the stores before it waits for them
// (a failed store forwarding; perf put a tenth of the path tracer's time in RenderScene::intersect on such loads).
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
