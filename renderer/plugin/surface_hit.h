#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include "renderer/math/transform.h"
#include "renderer/math/vec3.h"
#include "renderer/plugin/placement_record.h"

namespace isotrace {

class Material;
struct SceneObject;

// The materials of a hit on a composite surface whose parts blend (blob elements with materials of their own):
// up to four parts, weights summing to one. count 0: no blend, the hit's material alone.
struct MaterialBlend {
    static constexpr int kMaxParts = 4;
    std::array<std::uint32_t, kMaxParts> part{};
    std::array<float, kMaxParts> weight{};
    int count = 0;
};

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
    // For textures and the shading frame:
    Vec3f dpdu, dpdv;          // world-space derivatives of position along uv; zero where the shape has no uv
    Vec3f tangent;             // unit, perpendicular to shading_normal: the frame's x axis; zero lets the frame choose
    float footprint = 0;       // world-space width of the pixel's footprint at the hit (ray cone); 0: a point
    const SceneObject* object = nullptr;  // the object hit: its shape and materials (shared by the copies of a placement)
    // A placed copy's record (the object is the copies' shared one); null: the object is placed by its to_world.
    const PlacementRecord* placement = nullptr;
    MaterialBlend blend;

    // The object's placement, for object-space textures and frames: object->to_world, a placed copy's transform
    // computed from its record into `computed`, or the identity without an object. A handle rather than a Transform
    // in the hit: the 256 bytes were copied several times per hit, and most hits never read them.
    const Transform& to_world(std::optional<Transform>& computed) const;

    // Origin for a ray leaving the surface in `direction`: pushed off along the geometric normal, to the
    // side the ray travels, by the position error bound, so the ray cannot re-hit the surface it left.
    Vec3f spawn_origin(const Vec3f& direction) const {
        const float side = dot(geometric_normal, direction) >= 0 ? 1.0f : -1.0f;
        return position + geometric_normal * (side * position_error);
    }
};

}  // namespace isotrace
