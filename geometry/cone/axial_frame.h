#pragma once
// A right-handed orthonormal frame around an axis, for the shapes of revolution (frustum, torus): their equations
// are solved and their uv measured in it. Local coordinates are (along reference, along axis × reference, along
// axis) from the origin.
#include <algorithm>
#include <cmath>

#include "renderer/math/transform.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct AxialFrame {
    Vec3d origin;
    Vec3d axis{0, 1, 0};       // unit
    Vec3d reference{0, 0, 1};  // unit, perpendicular to the axis: where the angle around the axis is 0

    // The frame at `origin` around the unit `axis`, its reference the coordinate axis least aligned with it (z, then
    // x, then y on ties, so that an upright shape starts its angle at +z as a sphere's u does), made perpendicular.
    static AxialFrame around(const Vec3d& origin, const Vec3d& axis) {
        const Vec3d candidates[] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
        Vec3d best = candidates[0];
        for (const Vec3d& e : candidates)
            if (std::abs(dot(e, axis)) < std::abs(dot(best, axis))) best = e;
        return {origin, axis, normalize(best - axis * dot(best, axis))};
    }

    // How far a unit circle around the axis reaches from its centre along each coordinate i: √(1 − axisᵢ²).
    Vec3d circle_reach() const {
        return {std::sqrt(std::max(0.0, 1 - axis.x * axis.x)), std::sqrt(std::max(0.0, 1 - axis.y * axis.y)),
                std::sqrt(std::max(0.0, 1 - axis.z * axis.z))};
    }
    Vec3d binormal() const { return cross(axis, reference); }
    Vec3d local_point(const Vec3d& p) const { return local_vector(p - origin); }
    Vec3d local_vector(const Vec3d& v) const { return {dot(v, reference), dot(v, binormal()), dot(v, axis)}; }
    Vec3d world_vector(const Vec3d& v) const { return reference * v.x + binormal() * v.y + axis * v.z; }

    // The frame carried by a similarity (lengths scale by its factor; a mirror keeps the frame right-handed, so
    // angles then run the other way round on the mirrored shape).
    void transform(const Transform& to_world) {
        origin = to_world.point(origin);
        axis = normalize(to_world.vector(axis));
        const Vec3d r = to_world.vector(reference);
        reference = normalize(r - axis * dot(r, axis));
    }
};

}  // namespace isotrace
