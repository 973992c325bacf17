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
inline constexpr std::uint64_t kSweepTubeTrianglePeakBytes = 200;

// Throws std::invalid_argument for steps out of range (at most 4096 each). A vertex's uv is (t, θ/2π): u along
// the sweep's curve, v around it; the caps' centres have (0, ½) and (1, ½). The grid closes around through
// shared vertices (v = 0), so that a tube is closed by index; unwrap_tube_seams gives its uvs a seam.
TriangleMeshData tessellate(const SweepSurface& sweep, const SweepTessellation& options = {});

// For tubes of tessellate() whose normals are final: the triangles that close a tube around (from v just below 1
// to v = 0) get copies of their corners at v = 0 with v = 1, the position and normal unchanged, so that uv runs on
// across the seam instead of back around the tube. Does nothing to a mesh without uvs.
void unwrap_tube_seams(TriangleMeshData& tubes);

}  // namespace isotrace
