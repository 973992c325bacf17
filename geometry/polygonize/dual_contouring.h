#pragma once
// Dual contouring (Ju et al. 2002) on a lattice, manifold variant: the vertices are those of dual_vertices.h (one
// per cycle of a cell's marching-cubes pattern, or one per collapsed octree leaf after octree_simplification.h).
// Every cut lattice edge becomes the polygon of the vertices owning it in the cells around it: a quad (a triangle
// where two of the cells share a collapsed leaf), or on a spherical lattice's polar axis a ring of 2^L vertices
// closed by a fan around a ghost vertex on the axis.
//
// Guarantee: the mesh is the dual of the marching-cubes surface on the same lattice, so it is closed and
// consistently oriented wherever that one is, and a closed 2-manifold for a closed surface. One place needs a
// repair for that: where two cells sharing an ambiguous face both join that face's two segments into one cycle (a
// tunnel through the face), their two vertices would be joined by two dual edges, one per segment, and the edge
// between them would belong to four triangles. One of the two segments (the one round the face's inside corner
// with the smaller key) gets a vertex of its own, at the QEF minimiser of its two crossings, which the polygons of
// its two edges pass through (a "split" vertex). Vertices are clamped to their cells, so the mesh cannot stray
// from the lattice cells that hold the surface, but triangles may intersect each other.
#include <cstddef>

#include "geometry/mesh/triangle_mesh_data.h"
#include "geometry/polygonize/dual_vertices.h"

namespace isotrace {

// Where the ghost vertex closing a polar ring goes (all on the axis).
enum class PoleCap {
    AxisRoot,            // the surface's crossing of the axis (the root of f along the axial edge)
    // The paper's (our reading of its projection "in the direction of the surface normal"): where the tangent
    // plane at each ring vertex meets the axis, averaged — the surface continued to first order.
    NormalProjection,
    VerticalProjection,  // the earlier method's flat cap: the ring vertices' mean height on the axis
};

struct DualContouringStatistics {
    std::size_t cell_vertices = 0;     // vertices of cells or collapsed leaves
    std::size_t ghost_vertices = 0;
    std::size_t split_vertices = 0;    // one per tunnel through an ambiguous face (above)
    std::size_t clamped_vertices = 0;  // QEF minimisers that fell outside their cell
    std::size_t open_edges = 0;        // cut edges with a cell around them that the descent did not keep (a bug)
};

TriangleMeshData dual_contour(const LatticeSamples& samples, const Lattice& lattice, const ImplicitField& field,
                              const DualVertices& vertices, PoleCap pole_cap, DualContouringStatistics& statistics);

}  // namespace isotrace
