#include "geometry/polygonize/dual_contouring.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

#include "geometry/polygonize/cube_cycles.h"
#include "geometry/polygonize/mesh_normals.h"
#include "geometry/polygonize/qef.h"

namespace isotrace {
namespace {

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

int bit_on(int cube_edge, int axis) {
    const int a = cube_edge / 4;
    return axis == (a + 1) % 3 ? (cube_edge & 1) : ((cube_edge >> 1) & 1);
}

// Cube edge `cube_edge` moved to coordinate `side` on `axis` (a parallel edge of the same cell).
int with_bit(int cube_edge, int axis, int side) {
    const int a = cube_edge / 4;
    const int mask = axis == (a + 1) % 3 ? 1 : 2;
    return (cube_edge & ~mask) | (side ? mask : 0);
}

// The four edges of face (axis, side) of a cube all cut and on one cycle: the cell's surface joins both segments
// of the ambiguous face.
bool joins_both_segments(std::uint8_t pattern, int axis, int side) {
    const CubeCycles& cycles = cube_cycles(pattern);
    int cycle = -1;
    for (int e = 0; e < 12; ++e) {
        if (e / 4 == axis || bit_on(e, axis) != side) continue;
        if (cycles.cycle_of_edge[e] < 0 || (cycle >= 0 && cycles.cycle_of_edge[e] != cycle)) return false;
        cycle = cycles.cycle_of_edge[e];
    }
    return true;
}

LatticeIndex corner_of(const LatticeIndex& cell, int corner) {
    return {cell[0] + (corner & 1), cell[1] + ((corner >> 1) & 1), cell[2] + ((corner >> 2) & 1)};
}

// One segment of an ambiguous face: the cells on either side (smaller key first) and the inside corner it cuts off.
using SegmentKey = std::tuple<LatticeKey, LatticeKey, LatticeKey>;

class SplitVertices {
public:
    SplitVertices(const LatticeSamples& samples, const Lattice& lattice, std::vector<Vec3d>& positions)
        : samples_(samples), lattice_(lattice), positions_(positions) {}

    // For the cut edge `cube_edge` of cell a, whose polygon passes on to the neighbour b: the split vertex between
    // their vertices, or none.
    std::optional<std::uint32_t> between(const EdgeNeighbour& a, std::size_t a_cell, const EdgeNeighbour& b,
                                         std::size_t b_cell) {
        const int n = lattice_.cells_per_axis();
        int axis = 0;
        while (axis < 3 && a.cell[axis] == b.cell[axis]) ++axis;
        if (axis == 3) return std::nullopt;
        const int side = ((b.cell[axis] - a.cell[axis]) % n + n) % n == 1 ? 1 : 0;
        const std::uint8_t pattern = samples_.inside[a_cell];
        if (!joins_both_segments(pattern, axis, side) || !joins_both_segments(samples_.inside[b_cell], axis, 1 - side))
            return std::nullopt;
        // The edge as an edge of this face of a, and the face's inside corners.
        const int edge = with_bit(a.cube_edge, axis, side);
        const auto ends = cube_edge_corners(edge);
        const int inside_end = (pattern >> ends[0]) & 1 ? ends[0] : ends[1];
        const auto key_of = [&](int corner) { return lattice_key(lattice_.canonical_corner(corner_of(a.cell, corner))); };
        LatticeKey smallest = ~LatticeKey(0);
        for (int c = 0; c < 8; ++c)
            if (((c >> axis) & 1) == side && ((pattern >> c) & 1)) smallest = std::min(smallest, key_of(c));
        if (key_of(inside_end) != smallest) return std::nullopt;  // the other segment is split
        const LatticeKey ka = samples_.cells[a_cell], kb = samples_.cells[b_cell];
        const SegmentKey key{std::min(ka, kb), std::max(ka, kb), smallest};
        const auto [at, added] = split_.try_emplace(key, std::uint32_t(positions_.size()));
        if (added) positions_.push_back(place(a.cell, ka < kb ? a.cell : b.cell, edge, inside_end, axis, side));
        return at->second;
    }
    std::size_t count() const { return split_.size(); }

private:
    // The minimiser of the QEF of the segment's two crossings, in the cell with the smaller key.
    Vec3d place(const LatticeIndex& cell, const LatticeIndex& home, int edge, int inside_end, int axis, int side) const {
        int partner = -1;
        for (int e = 0; e < 12; ++e) {
            if (e == edge || e / 4 == axis || bit_on(e, axis) != side) continue;
            const auto ends = cube_edge_corners(e);
            if (ends[0] == inside_end || ends[1] == inside_end) partner = e;
        }
        std::size_t s[2] = {sample_of(samples_, lattice_, cell, edge), sample_of(samples_, lattice_, cell, partner)};
        std::sort(s, s + 2);
        Qef qef;
        for (std::size_t k : s) qef.add(samples_.crossings[k], samples_.gradients[k]);
        return lattice_.clamp_to_cell(qef.solve(), home);
    }

    const LatticeSamples& samples_;
    const Lattice& lattice_;
    std::vector<Vec3d>& positions_;
    std::map<SegmentKey, std::uint32_t> split_;
};

// Triangles of one polygon, counter-clockwise.
void triangulate(const std::vector<std::uint32_t>& polygon, int fan_apex, const std::vector<Vec3d>& positions,
                 std::vector<std::array<std::uint32_t, 3>>& triangles) {
    const std::size_t n = polygon.size();
    if (fan_apex >= 0) {
        for (std::size_t k = 1; k + 1 < n; ++k)
            triangles.push_back({polygon[std::size_t(fan_apex)], polygon[(std::size_t(fan_apex) + k) % n],
                                 polygon[(std::size_t(fan_apex) + k + 1) % n]});
        return;
    }
    if (n == 3) {
        triangles.push_back({polygon[0], polygon[1], polygon[2]});
        return;
    }
    // A quad: split along the shorter diagonal.
    const auto d = [&](int i, int j) { return length(positions[polygon[std::size_t(i)]] - positions[polygon[std::size_t(j)]]); };
    if (d(0, 2) <= d(1, 3)) {
        triangles.push_back({polygon[0], polygon[1], polygon[2]});
        triangles.push_back({polygon[0], polygon[2], polygon[3]});
    } else {
        triangles.push_back({polygon[0], polygon[1], polygon[3]});
        triangles.push_back({polygon[1], polygon[2], polygon[3]});
    }
}

}  // namespace

TriangleMeshData dual_contour(const LatticeSamples& samples, const Lattice& lattice, const ImplicitField& field,
                              const DualVertices& dual, PoleCap pole_cap, DualContouringStatistics& statistics) {
    statistics = {};
    std::vector<Vec3d> vertices = dual.positions;
    statistics.cell_vertices = vertices.size();
    statistics.clamped_vertices = dual.clamped;
    SplitVertices split(samples, lattice, vertices);

    TriangleMeshData mesh;
    mesh.triangles.reserve(2 * samples.edges.size());  // a quad per cut edge, mostly: no regrowth at the peak
    std::vector<EdgeNeighbour> around;
    std::vector<std::size_t> cells;
    std::vector<std::uint32_t> polygon;
    std::vector<Vec3d> ring, ring_normals;
    for (std::size_t e = 0; e < samples.edges.size(); ++e) {
        const int axis = int(samples.edges[e] & 3);
        const LatticeIndex corner = lattice_index(samples.edges[e] >> 2);
        lattice.cells_around_edge(corner, axis, around);
        cells.clear();
        for (const EdgeNeighbour& neighbour : around) {
            const auto cell = samples.cell(lattice_key(neighbour.cell));
            if (!cell) break;
            cells.push_back(*cell);
        }
        if (around.empty() || cells.size() != around.size()) {
            ++statistics.open_edges;
            continue;
        }
        polygon.clear();
        int split_at = -1;
        for (std::size_t k = 0; k < around.size(); ++k) {
            const std::uint32_t v = dual.vertex(cells[k], cube_cycles(samples.inside[cells[k]]).cycle_of_edge[around[k].cube_edge]);
            if (polygon.empty() || polygon.back() != v) polygon.push_back(v);  // cells of one collapsed leaf
            const std::size_t next = (k + 1) % around.size();
            if (const auto s = split.between(around[k], cells[k], around[next], cells[next])) {
                split_at = int(polygon.size());
                polygon.push_back(*s);
            }
        }
        while (polygon.size() > 1 && polygon.back() == polygon.front()) polygon.pop_back();
        if (polygon.size() < 3) continue;  // inside one leaf, or across a face between two
        // Counter-clockwise about +axis faces +axis: right when the inside is at the lower end.
        if (!samples.lower_inside[e]) {
            std::reverse(polygon.begin(), polygon.end());
            if (split_at >= 0) split_at = int(polygon.size()) - 1 - split_at;
        }
        if (around.size() == 4) {
            triangulate(polygon, split_at, vertices, mesh.triangles);
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
    statistics.split_vertices = split.count();
    for (const Vec3d& v : vertices) mesh.positions.push_back(Vec3f(v));
    mesh.normals = field_normals(field, mesh.positions);
    return mesh;
}

}  // namespace isotrace
