#include "geometry/polygonize/dual_vertices.h"

#include <numeric>

#include "renderer/core/parallel_for.h"

namespace isotrace {

std::size_t sample_of(const LatticeSamples& samples, const Lattice& lattice, const LatticeIndex& cell, int cube_edge) {
    const int c = cube_edge_corners(cube_edge)[0];
    LatticeIndex corner = {cell[0] + (c & 1), cell[1] + ((c >> 1) & 1), cell[2] + ((c >> 2) & 1)};
    lattice.canonical_edge(corner, cube_edge / 4);
    return *samples.edge(edge_key(corner, cube_edge / 4));
}

Qef cycle_qef(const LatticeSamples& samples, const Lattice& lattice, const LatticeIndex& cell, const CubeCycle& cycle) {
    Qef qef;
    std::size_t used[12];
    int count = 0;
    for (int j = 0; j < cycle.length; ++j) {
        const std::size_t s = sample_of(samples, lattice, cell, cycle.edges[j]);
        bool seen = false;  // the polar edge appears twice in a cell at the pole
        for (int k = 0; k < count; ++k) seen = seen || used[k] == s;
        if (seen) continue;
        used[count++] = s;
        qef.add(samples.crossings[s], samples.gradients[s]);
    }
    return qef;
}

DualVertices cell_vertices(const LatticeSamples& samples, const Lattice& lattice) {
    DualVertices result;
    result.first_cycle.assign(samples.cells.size() + 1, 0);
    for (std::size_t i = 0; i < samples.cells.size(); ++i)
        result.first_cycle[i + 1] = result.first_cycle[i] + std::uint32_t(cube_cycles(samples.inside[i]).count);
    result.positions.resize(result.first_cycle.back());
    result.vertex_of_cycle.resize(result.positions.size());
    std::iota(result.vertex_of_cycle.begin(), result.vertex_of_cycle.end(), 0u);
    std::vector<std::uint8_t> clamped(result.positions.size());
    parallel_for(std::size_t(0), samples.cells.size(), [&](std::size_t i) {
        const LatticeIndex cell = lattice_index(samples.cells[i]);
        const CubeCycles& cycles = cube_cycles(samples.inside[i]);
        for (int k = 0; k < cycles.count; ++k) {
            const Vec3d x = cycle_qef(samples, lattice, cell, cycles.cycles[k]).solve();
            const Vec3d kept = lattice.clamp_to_cell(x, cell);
            result.positions[result.first_cycle[i] + std::uint32_t(k)] = kept;
            clamped[result.first_cycle[i] + std::uint32_t(k)] = !(length(kept - x) <= 1e-12 * (1 + length(x)));
        }
    });
    for (std::uint8_t c : clamped) result.clamped += c;
    return result;
}

}  // namespace isotrace
