#pragma once
#include <array>
#include <cstdint>

#include "renderer/math/vec3.h"

namespace isotrace {

class Material;

// A ray's nearest surface, in world space.
struct SurfaceHit {
    float t = 0;
    Vec3f position;
    Vec3f geometric_normal;  // unit; orientation as the geometry defines it (outward for closed shapes)
    Vec3f shading_normal;    // unit; same side as geometric_normal
    std::array<float, 2> uv{0, 0};
    std::uint32_t object_index = 0;
    std::uint32_t primitive_id = 0;
    const Material* material = nullptr;
    float position_error = 0;  // bound on |position - exact hit|, for offsetting secondary rays

    // Origin for a ray leaving the surface in `direction`: pushed off along the geometric normal, to the
    // side the ray travels, by the position error bound, so the ray cannot re-hit the surface it left.
    Vec3f spawn_origin(const Vec3f& direction) const {
        const float side = dot(geometric_normal, direction) >= 0 ? 1.0f : -1.0f;
        return position + geometric_normal * (side * position_error);
    }
};

}  // namespace isotrace
