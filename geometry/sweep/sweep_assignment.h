#pragma once
// Which sweep of a hierarchy each mesh vertex follows. The paper segments the parts by hand; here a vertex inside
// exactly one sweep (d ≤ 0), or named by a vertex group, follows that sweep, and the others — inside several
// sweeps (a spout's root inside the body's sweep) or inside none — take the sweep of the nearest such vertex
// along the mesh (shortest path over edges, among the sweeps that bind them). Following the surface, not the
// depth in each sweep, keeps a part's vertices together: a body wall next to the spout's root follows the body,
// the spout's end inside the body follows the spout. Vertices no seed reaches (a loose piece inside several
// sweeps) follow the sweep they lie deepest in (smallest (r + d)/r); vertices no sweep binds follow none (−1).
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/mesh/triangle_mesh_data.h"
#include "geometry/sweep/vertex_binding.h"

namespace isotrace {

using SweepBindings = std::vector<std::vector<std::optional<VertexBinding>>>;  // [sweep][vertex]
using VertexNeighbours = std::vector<std::vector<std::uint32_t>>;

// Neighbours of each vertex over triangle edges; vertices repeated at one position (seams) are joined.
VertexNeighbours vertex_neighbours(const TriangleMeshData& mesh);

// `bindings[s][v]`: vertex v bound to sweep s, or not. `grouped[v]`: the sweep a vertex group puts v in, or −1
// (empty: no groups). Returns one sweep index (or −1) per vertex.
std::vector<int> assign_sweeps(const TriangleMeshData& mesh, const VertexNeighbours& next, const SweepBindings& bindings,
                               const std::vector<int>& grouped);

// Where two sweeps' vertices meet, they move differently: a vertex within a distance w along the mesh of
// another sweep's vertices (and bound to it) also follows that sweep, with weight 1 − distance / w, so the seam
// is spread over a band instead of tearing. w = `widths[s]` for the other sweep s and w of the vertex's own sweep,
// whichever is smaller. Returns per vertex its sweeps and their weights (summing to 1); none for unowned vertices.
struct SweepShare {
    int sweep = -1;
    double weight = 0;
};
std::vector<std::vector<SweepShare>> blend_sweeps(const TriangleMeshData& mesh, const VertexNeighbours& next,
                                                  const SweepBindings& bindings, const std::vector<int>& owner,
                                                  const std::vector<double>& widths);

}  // namespace isotrace
