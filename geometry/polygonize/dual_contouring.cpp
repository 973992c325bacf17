#include "geometry/polygonize/dual_contouring.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "geometry/polygonize/cube_cycles.h"
#include "geometry/polygonize/mesh_normals.h"
#include "geometry/polygonize/qef.h"

namespace isotrace {
namespace {

LatticeIndex edge_start(const LatticeIndex& cell, int cube_edge) {
    const int corner = cube_edge_corners(cube_edge)[0];
    return {cell[0] + (corner & 1), cell[1] + ((corner >> 1) & 1), cell[2] + ((corner >> 2) & 1)};
}

// The index of cut lattice edge `cube_edge` of `cell` in the samples.
std::size_t sample_of(const LatticeSamples& samples, const Lattice& lattice, const LatticeIndex& cell, int cube_edge) {
    LatticeIndex corner = edge_start(cell, cube_edge);
    lattice.canonical_edge(corner, cube_edge / 4);
    return *samples.edge(edge_key(corner, cube_edge / 4));
}

// The vertex of one cycle of a cell: the QEF minimiser over the cycle's crossings, kept in the cell.
Vec3d cycle_vertex(const LatticeSamples& samples, const Lattice& lattice, const LatticeIndex& cell,
                   const CubeCycle& cycle, bool& clamped) {
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
    const Vec3d x = qef.solve();
    const Vec3d kept = lattice.clamp_to_cell(x, cell);
    clamped = !(length(kept - x) <= 1e-12 * (1 + length(x)));
    return kept;
}

// The ghost vertex on the polar axis for a ring of vertices around the axial edge from a to b.
Vec3d ghost_vertex(PoleCap cap, const Vec3d& crossing, const Vec3d& a, const Vec3d& b,
                   const std::vector<Vec3d>& ring, const std::vector<Vec3d>& ring_normals) {
    if (cap == PoleCap::AxisRoot) return crossing;
    const Vec3d axis = normalize(b - a);
    double sum = 0;
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const Vec3d w = ring[k] - a;
        double s = dot(w, axis);  // perpendicular projection
        if (cap == PoleCap::NormalProjection) {
            // Where the tangent plane through ring[k] (normal n) meets the axis: the surface extended from the
            // ring vertex to first order.
            const Vec3d& n = ring_normals[k];
            const double along = dot(n, axis);
            if (std::abs(along) > 1e-3) s = dot(n, w) / along;
        }
        sum += s;
    }
    return a + axis * (sum / double(ring.size()));
}

}  // namespace

TriangleMeshData dual_contour(const LatticeSamples& samples, const Lattice& lattice, const ImplicitField& field,
                              PoleCap pole_cap, DualContouringStatistics& statistics) {
    statistics = {};
    // One vertex per cycle, numbered in cell order.
    std::vector<std::uint32_t> first_vertex(samples.cells.size() + 1, 0);
    for (std::size_t i = 0; i < samples.cells.size(); ++i)
        first_vertex[i + 1] = first_vertex[i] + std::uint32_t(cube_cycles(samples.inside[i]).count);
    std::vector<Vec3d> vertices(first_vertex.back());
    std::vector<std::uint8_t> clamped(vertices.size());
    tbb::parallel_for(std::size_t(0), samples.cells.size(), [&](std::size_t i) {
        const LatticeIndex cell = lattice_index(samples.cells[i]);
        const CubeCycles& cycles = cube_cycles(samples.inside[i]);
        for (int k = 0; k < cycles.count; ++k) {
            bool was_clamped = false;
            vertices[first_vertex[i] + k] = cycle_vertex(samples, lattice, cell, cycles.cycles[k], was_clamped);
            clamped[first_vertex[i] + k] = was_clamped;
        }
    });
    statistics.cell_vertices = vertices.size();
    for (std::uint8_t c : clamped) statistics.clamped_vertices += c;

    TriangleMeshData mesh;
    std::vector<EdgeNeighbour> around;
    std::vector<std::uint32_t> polygon;
    std::vector<Vec3d> ring, ring_normals;
    for (std::size_t e = 0; e < samples.edges.size(); ++e) {
        const int axis = int(samples.edges[e] & 3);
        const LatticeIndex corner = lattice_index(samples.edges[e] >> 2);
        lattice.cells_around_edge(corner, axis, around);
        polygon.clear();
        for (const EdgeNeighbour& neighbour : around) {
            const auto cell = samples.cell(lattice_key(neighbour.cell));
            if (!cell) break;
            polygon.push_back(first_vertex[*cell] + std::uint32_t(cube_cycles(samples.inside[*cell]).cycle_of_edge[neighbour.cube_edge]));
        }
        if (around.empty() || polygon.size() != around.size()) {
            ++statistics.open_edges;
            continue;
        }
        // Counter-clockwise about +axis faces +axis: right when the inside is at the lower end.
        if (!samples.lower_inside[e]) std::reverse(polygon.begin(), polygon.end());
        if (polygon.size() == 4) {
            // Split along the shorter diagonal.
            const auto d = [&](int i, int j) { return length(vertices[polygon[i]] - vertices[polygon[j]]); };
            if (d(0, 2) <= d(1, 3)) {
                mesh.triangles.push_back({polygon[0], polygon[1], polygon[2]});
                mesh.triangles.push_back({polygon[0], polygon[2], polygon[3]});
            } else {
                mesh.triangles.push_back({polygon[0], polygon[1], polygon[3]});
                mesh.triangles.push_back({polygon[1], polygon[2], polygon[3]});
            }
            continue;
        }
        ring.clear();
        ring_normals.clear();
        for (std::uint32_t v : polygon) {
            ring.push_back(vertices[v]);
            if (pole_cap == PoleCap::NormalProjection) ring_normals.push_back(normalize(field.gradient(vertices[v])));
        }
        LatticeIndex upper = corner;
        ++upper[axis];
        const auto ghost = std::uint32_t(vertices.size());
        vertices.push_back(ghost_vertex(pole_cap, samples.crossings[e], lattice.position(Vec3d(corner[0], corner[1], corner[2])),
                                        lattice.position(Vec3d(upper[0], upper[1], upper[2])), ring, ring_normals));
        ++statistics.ghost_vertices;
        for (std::size_t k = 0; k < polygon.size(); ++k)
            mesh.triangles.push_back({ghost, polygon[k], polygon[(k + 1) % polygon.size()]});
    }
    for (const Vec3d& v : vertices) mesh.positions.push_back(Vec3f(v));
    mesh.normals = field_normals(field, mesh.positions);
    return mesh;
}

}  // namespace isotrace
