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
};

}  // namespace isotrace
