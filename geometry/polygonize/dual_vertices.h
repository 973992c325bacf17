#pragma once
// The vertices of dual contouring, before its faces: one per cycle of each surface cell's marching-cubes pattern
// (cube_cycles.h) — one per connected component of the surface in the cell (manifold dual contouring) — at the
// minimiser of the QEF over that cycle's Hermite data (qef.h), clamped to the cell. Octree simplification
// (octree_simplification.h) later lets several cycles share one vertex.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/polygonize/cube_cycles.h"
#include "geometry/polygonize/lattice_samples.h"
#include "geometry/polygonize/qef.h"

namespace isotrace {

struct DualVertices {
    std::vector<std::uint32_t> first_cycle;      // per surface cell, its first cycle's number; one more at the end
    std::vector<std::uint32_t> vertex_of_cycle;  // per cycle: the vertex it is drawn with
    std::vector<Vec3d> positions;
    std::size_t clamped = 0;                     // QEF minimisers that fell outside their cell

    std::uint32_t vertex(std::size_t cell, int cycle) const { return vertex_of_cycle[first_cycle[cell] + std::uint32_t(cycle)]; }
};

// The index of cut lattice edge `cube_edge` of `cell` in the samples.
std::size_t sample_of(const LatticeSamples& samples, const Lattice& lattice, const LatticeIndex& cell, int cube_edge);

// The QEF of one cycle of a cell: a plane per distinct cut edge of the cycle.
Qef cycle_qef(const LatticeSamples& samples, const Lattice& lattice, const LatticeIndex& cell, const CubeCycle& cycle);

// One vertex per cycle, numbered in cell order.
DualVertices cell_vertices(const LatticeSamples& samples, const Lattice& lattice);

}  // namespace isotrace
