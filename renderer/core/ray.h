#pragma once
#include <limits>

#include "renderer/math/vec3.h"

namespace isotrace {

// The finite world: every coordinate of a scene lies within this distance of the origin on each axis. Embree traces
// only rays whose origin and direction components are at most its FLT_LARGE (1.844e18) in magnitude (beyond, its
// assertion aborts the process) and silently drops geometry bounds beyond it; the margin lets rays leave surfaces
// at the limit. Scenes are checked against it where they are read (renderer/params/world_limit.h), rays where they
// are traced (is_traceable, renderer/embree/embree_ray.h).
inline constexpr double kWorldLimit = 1e18;

// A ray segment origin + t * direction, t in [t_near, t_far]. Direction need not be unit length.
struct Ray {
    Vec3f origin;
    Vec3f direction;
    float t_near = 0;
    float t_far = std::numeric_limits<float>::infinity();
    // The ray's share of a pixel, a cone around it: its width at the origin and its growth per unit of distance
    // (t·|direction|). Hits report the width there (SurfaceHit::footprint), for filtering textures.
    float cone_width = 0;
    float cone_spread = 0;

    Vec3f at(float t) const { return origin + direction * t; }
};

}  // namespace isotrace
