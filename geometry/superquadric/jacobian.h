#pragma once
// The Jacobian of one deformation stage, stored by columns (∂X/∂x, ∂X/∂y, ∂X/∂z), and the map that carries a
// surface normal through it.
#include "renderer/math/vec3.h"

namespace isotrace {

struct Jacobian {
    Vec3d column[3];

    // det(J)·J⁻ᵀ·n: the deformed normal up to a positive factor (every supported deformation has det J > 0).
    // Rows of J⁻¹ are the cross products of column pairs over det J, so J⁻ᵀ·n is their combination.
    Vec3d transform_normal(const Vec3d& n) const {
        return cross(column[1], column[2]) * n.x + cross(column[2], column[0]) * n.y + cross(column[0], column[1]) * n.z;
    }
    // J⁻¹·v by Cramer's rule: the vector w with J·w = v (a curve's velocity carried back through the stage).
    Vec3d solve(const Vec3d& v) const {
        const Vec3d c12 = cross(column[1], column[2]);
        return Vec3d(dot(v, c12), dot(column[0], cross(v, column[2])), dot(column[0], cross(column[1], v))) /
               dot(column[0], c12);
    }
};

}  // namespace isotrace
