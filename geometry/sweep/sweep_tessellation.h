#pragma once
// Triangles of a sweep surface on a regular (θ, t) grid, counter-clockwise seen from outside, optionally closed
// by fans at both ends: the translucent tubes of the figures, and closed meshes whose volume tests eq. (3).
#include <cstdint>

#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

class SweepSurface;

struct SweepTessellation {
    int theta_steps = 48;  // ≥ 3
    int t_steps = 64;      // ≥ 1
    bool caps = true;

    // The triangles tessellate() makes, so that their memory can be charged first.
    std::uint64_t triangle_count() const {
        return 2 * std::uint64_t(theta_steps) * (std::uint64_t(t_steps) + (caps ? 1 : 0));
    }
};

// Peak memory per triangle of a tube from its tessellation to the traced shape (the tube's mesh and its copy in
// the shape, vertex normals, Embree's copy and BVH): measured as peak resident memory over triangle counts.
inline constexpr std::uint64_t kSweepTubeTrianglePeakBytes = 190;

// Throws std::invalid_argument for steps out of range (at most 4096 each).
TriangleMeshData tessellate(const SweepSurface& sweep, const SweepTessellation& options = {});

}  // namespace isotrace
