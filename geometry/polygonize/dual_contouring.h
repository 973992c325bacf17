#pragma once
// Dual contouring (Ju et al. 2002) on a lattice, manifold variant: a cell gets one vertex per cycle of its
// marching-cubes pattern (cube_cycles.h) — one per connected component of the surface in the cell, as in
// manifold dual contouring (Schaefer, Ju & Warren 2007) — placed by the cell's QEF over that cycle's Hermite data
// (qef.h) and clamped to the cell. Every cut lattice edge becomes the polygon of the vertices owning it in the
// cells around it: a quad, or on a spherical lattice's polar axis a ring of 2^L vertices closed by a fan around a
// ghost vertex on the axis.
//
// Guarantee: the mesh is the dual of the marching-cubes surface on the same lattice, so it is closed and
// consistently oriented wherever that one is, and a 2-manifold except where two cells sharing a face both join
// that face's two segments into one cycle (a tunnel through an ambiguous face): the edge between their two vertices
// then belongs to four triangles. Vertices are clamped to their cells, so the mesh cannot stray from the
// lattice cells that hold the surface, but triangles may intersect each other.
#include <cstddef>

#include "geometry/mesh/triangle_mesh_data.h"
#include "geometry/polygonize/lattice_samples.h"

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
    std::size_t cell_vertices = 0;
    std::size_t ghost_vertices = 0;
    std::size_t clamped_vertices = 0;  // QEF minimisers that fell outside their cell
    std::size_t open_edges = 0;        // cut edges with a cell around them that the descent did not keep (a bug)
};

TriangleMeshData dual_contour(const LatticeSamples& samples, const Lattice& lattice, const ImplicitField& field,
                              PoleCap pole_cap, DualContouringStatistics& statistics);

}  // namespace isotrace
