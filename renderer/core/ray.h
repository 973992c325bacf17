#pragma once
#include <limits>

#include "renderer/math/vec3.h"

namespace isotrace {

// A ray segment origin + t * direction, t in [t_near, t_far]. Direction need not be unit length.
struct Ray {
    Vec3f origin;
    Vec3f direction;
    float t_near = 0;
    float t_far = std::numeric_limits<float>::infinity();

    Vec3f at(float t) const { return origin + direction * t; }
};

}  // namespace isotrace
