#pragma once
// Triangles of a set of attribute-based patches, with analytic normals and an error bound in world units. Each
// vertex's uv is its point of its patch's domain (patch_domain.h), so textures map through the domain.
//
// Each boundary curve is sampled once, at parameters shared by every patch that uses it (in either direction),
// and curve end points that a loop joins are welded to one point, so patches sharing a curve meet at bit-identical
// vertices: the mesh is watertight. Each patch keeps its own copies of its boundary vertices so that each carries
// the patch's own normal (adjacent patches generally meet at a crease).
//
// A patch is cut into sectors, one per side: the triangle from the domain's centre to the side. Rings at radial
// parameters ρ (0 at the centre, 1 on the boundary, shared by all sectors) cross each sector at the side's curve
// parameters. Refinement is local in both directions: where a triangle's edge midpoint or centroid lies farther
// than the tolerance from the surface point at the same domain point, the curve segment (shared by its patches)
// or the ring band (shared by the patch's sectors) is halved, until every test point is within the tolerance or
// the segment cap is reached.
#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/abm_patch/abm_patch.h"
#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace {

// Peak memory per triangle from the grids to the traced shape (grid vertices and triangles, the mesh with its
// normals, Embree's copy and BVH): measured as peak resident memory over triangle counts (docs/reliability.md).
inline constexpr std::uint64_t kPatchTrianglePeakBytes = 180;

struct PatchTessellationOptions {
    double tolerance = 1e-3;  // world units
    int max_segments = 256;   // cap per curve and per patch radially
    int segments = 0;         // > 0: exactly this many per curve and radially, no refinement (benchmarks, tests)
    // Called with the number of triangles before every round builds them, so that the caller can charge the
    // memory first (and throw to refuse).
    std::function<void(std::uint64_t triangles)> before_building = nullptr;
};

struct PatchTessellationReport {
    int rounds = 0;                  // refinement rounds
    double largest_deviation = 0;    // at the test points of the final mesh
    bool capped = false;             // the segment cap stopped refinement before the tolerance was met
};

// Throws std::invalid_argument for a tolerance that is not > 0 or segment counts outside 1 … 4096.
TriangleMeshData tessellate_patches(const std::vector<AbmPatch>& patches, const PatchTessellationOptions& options = {},
                                    PatchTessellationReport* report = nullptr);

}  // namespace isotrace
