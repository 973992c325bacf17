#pragma once
// The axis-aligned bounds of a transformed box (its eight corners mapped), for solids placed by a transform.
#include "renderer/math/box_corner.h"
#include "renderer/math/transform.h"
#include "renderer/plugin/shape.h"

namespace isotrace {

inline Bounds3f transformed_bounds(const Vec3d& lower, const Vec3d& upper, const Transform& transform) {
    Bounds3f result;
    for (int corner = 0; corner < 8; ++corner) {
        result.extend(Vec3f(transform.point(box_corner(lower, upper, corner))));
    }
    return result;
}

}  // namespace isotrace
