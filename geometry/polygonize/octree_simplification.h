#pragma once
// Simplification of dual contouring on the Cartesian octree by QEF error (Ju et al. 2002 §4.2), bottom up: an
// octree node whose eight children are leaves with at most one surface component each becomes one leaf with one
// vertex when
//   (a) the collapse keeps the topology (collapse_topology.h: the surface in the node is one disc meeting each
//       node face in at most one arc), and
//   (b) the vertex — the minimiser of the node's QEF (the sum of its children's), clamped to the node — lies
//       within `tolerance` of every tangent plane of the Hermite data in the node: √Q(x) ≤ tolerance, in scene
//       units (Q is a sum of squared distances to those planes, so each one is within √Q).
// The faces are then those of octree dual contouring over the minimal edges: each cut finest edge's polygon with
// every cell drawn by its leaf's vertex, repeated vertices merged, and polygons of fewer than three vertices dropped.
//
// Nothing else depends on the tolerance, so a larger tolerance collapses a superset of the nodes: the vertex count
// never rises with it.
#include <cstddef>

#include "geometry/polygonize/cartesian_lattice.h"
#include "geometry/polygonize/dual_vertices.h"

namespace isotrace {

struct SimplificationStatistics {
    std::size_t collapsed_nodes = 0;       // nodes made leaves (including those collapsed again later)
    std::size_t rejected_by_topology = 0;  // nodes whose children were all leaves, refused by (a)
    std::size_t rejected_by_error = 0;     // refused by (b)
    int coarsest_level = 0;                // the level of the largest leaf with surface (L when nothing collapsed)
};

// `vertices` comes from cell_vertices(samples, lattice); its cycles are redirected to the leaves' vertices.
SimplificationStatistics simplify_octree(const LatticeSamples& samples, const CartesianLattice& lattice,
                                         const ImplicitField& field, double tolerance, DualVertices& vertices);

}  // namespace isotrace
