#pragma once
// Tensor-product Bézier patches (Newell's teapot format, .bpt) and their tessellation into one welded triangle
// mesh. Format: the patch count, then per patch a line "du dv" (degrees) and (du+1)·(dv+1) lines "x y z",
// control point (i, j) at line i·(dv+1) + j. Evaluation goes through geometry/curves (Bézier curves).
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/core/memory_budget.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct BezierPatch {
    int degree_u = 3, degree_v = 3;
    std::vector<Vec3d> control_points;  // (degree_u + 1)·(degree_v + 1), row i = u index

    // S(u, v) and its partial derivatives, u, v ∈ [0, 1].
    struct Sample {
        Vec3d position, d_u, d_v;
    };
    Sample evaluate(double u, double v) const;
};

// Throws InputError naming `path` and the line for malformed files (counts, degrees 1…16, non-finite numbers,
// at most 100000 patches). The patches are charged to `memory` as they are read.
std::vector<BezierPatch> load_bezier_patches(const std::string& path, MemoryBudget& memory);

// Peak memory per tessellated quad, from the tessellation to the traced mesh shape (welding map, positions,
// normals, triangles, Embree's copy and BVH): measured as peak resident memory over patch counts.
inline constexpr std::uint64_t kBezierQuadPeakBytes = 460;

// Charges `memory` for tessellating `patch_count` patches at `steps` × `steps` quads each; throws InputError
// naming `path` with the figure when it does not fit.
void charge_bezier_tessellation(std::size_t patch_count, int steps, const std::string& path, MemoryBudget& memory);

// `steps` × `steps` quads per patch (1…256), split into triangles counter-clockwise in (u, v); vertices that
// coincide (shared patch edges, collapsed poles) are merged, so the result is one connected mesh; normals are
// area-weighted vertex normals (compute_vertex_normals).
TriangleMeshData tessellate_bezier_patches(const std::vector<BezierPatch>& patches, int steps);

}  // namespace isotrace
