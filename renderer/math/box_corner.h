#pragma once
// Corner `corner` (0–7) of the box [lower, upper]: bit k of the index picks the upper bound on axis k.
#include "renderer/math/vec3.h"

namespace isotrace {

template <class T>
Vec3T<T> box_corner(const Vec3T<T>& lower, const Vec3T<T>& upper, int corner) {
    return {(corner & 1 ? upper : lower).x, (corner & 2 ? upper : lower).y, (corner & 4 ? upper : lower).z};
}

}  // namespace isotrace
