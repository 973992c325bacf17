#pragma once
// Triangles of a sweep surface on a regular (θ, t) grid, counter-clockwise seen from outside, optionally closed
// by fans at both ends: the translucent tubes of the figures, and closed meshes whose volume tests eq. (3).
#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

class SweepSurface;

struct SweepTessellation {
    int theta_steps = 48;  // ≥ 3
    int t_steps = 64;      // ≥ 1
    bool caps = true;
};

// Throws std::invalid_argument for steps out of range (at most 4096 each).
TriangleMeshData tessellate(const SweepSurface& sweep, const SweepTessellation& options = {});

}  // namespace isotrace
