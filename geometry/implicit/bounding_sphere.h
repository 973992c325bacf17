#pragma once
#include <cmath>
#include <limits>

#include "geometry/implicit/metacube.h"

namespace isotrace {

// A sphere that contains an element's support, in 16 bytes: the first test of every listed element of every
// marched cell (sphere_prefilter.h) reads only these, not the far larger elements, so it touches little memory.
// Rounded so that it still contains the support: the radius grows by the centre's rounding.
struct alignas(16) BoundingSphere {
    float centre[3];
    float radius;

    static BoundingSphere of(const Metacube& element) {
        const Vec3d& c = element.centre();
        BoundingSphere sphere{{float(c.x), float(c.y), float(c.z)}, 0};
        const Vec3d rounding = c - Vec3d(sphere.centre[0], sphere.centre[1], sphere.centre[2]);
        const double reach = element.support_radius() + length(rounding);
        sphere.radius = std::nextafter(float(reach * (1 + 1e-9)), std::numeric_limits<float>::infinity());
        return sphere;
    }
    // False only when p is outside the element's support (its field and gradient are exactly 0 there).
    bool may_contain(const Vec3d& p) const {
        const Vec3d f = p - Vec3d(centre[0], centre[1], centre[2]);
        return dot(f, f) <= double(radius) * double(radius) * (1 + 1e-9);
    }
    // False only when the box [lower, upper] holds no point that may_contain accepts.
    bool may_meet(const Vec3d& lower, const Vec3d& upper) const {
        const Vec3d c(centre[0], centre[1], centre[2]);
        const Vec3d gap = max(max(lower - c, c - upper), Vec3d(0, 0, 0));
        return dot(gap, gap) <= double(radius) * double(radius) * (1 + 1e-9);
    }
};

static_assert(sizeof(BoundingSphere) == 16, "one vector load per sphere");

}  // namespace isotrace
