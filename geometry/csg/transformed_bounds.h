#pragma once
// The axis-aligned bounds of a transformed box (its eight corners mapped), for solids placed by a transform.
#include "renderer/math/transform.h"
#include "renderer/plugin/shape.h"

namespace isotrace {

inline Bounds3f transformed_bounds(const Vec3d& lower, const Vec3d& upper, const Transform& transform) {
    Bounds3f result;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p(corner & 1 ? upper.x : lower.x, corner & 2 ? upper.y : lower.y, corner & 4 ? upper.z : lower.z);
        result.extend(Vec3f(transform.point(p)));
    }
    return result;
}

}  // namespace isotrace
