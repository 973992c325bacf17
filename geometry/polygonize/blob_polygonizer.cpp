#include "geometry/polygonize/blob_polygonizer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/polygonize/marching_tetrahedra.h"
#include "renderer/core/parallel_for.h"
#include "renderer/core/parallel_sort.h"

namespace isotrace {
namespace {

constexpr int kBrickCells = 8;  // bricks of 8³ cells: the unit of sparsity and of parallel work
constexpr int kAxisBits = 20;
constexpr std::int64_t kAxisLimit = std::int64_t(1) << kAxisBits;
constexpr std::int64_t kAxisMask = kAxisLimit - 1;

using LatticePoint = std::array<std::int64_t, 3>;
// A lattice edge: the key of its lower lattice point shifted left by 3, or'ed with its direction bits (1..7).
using EdgeKey = std::uint64_t;
using KeyedTriangle = std::array<EdgeKey, 3>;

std::uint64_t pack(const LatticePoint& p) {
    return (std::uint64_t(p[2]) << (2 * kAxisBits)) | (std::uint64_t(p[1]) << kAxisBits) | std::uint64_t(p[0]);
}

LatticePoint unpack(std::uint64_t key) {
    return {std::int64_t(key & kAxisMask), std::int64_t((key >> kAxisBits) & kAxisMask),
            std::int64_t((key >> (2 * kAxisBits)) & kAxisMask)};
}

struct Lattice {
    Vec3d origin;
    double cell = 1;
    Vec3d point(const LatticePoint& p) const {
        return origin + Vec3d(double(p[0]), double(p[1]), double(p[2])) * cell;
    }
    LatticePoint cell_of(const Vec3d& position) const {
        LatticePoint c{};
        for (int k = 0; k < 3; ++k) c[std::size_t(k)] = std::int64_t(std::floor((position[k] - origin[k]) / cell));
        return c;
    }
};

void check_cell_size(double cell_size) {
    if (!(std::isfinite(cell_size) && cell_size > 0))
        throw std::invalid_argument("cell_size: must be finite and > 0, got " + std::to_string(cell_size));
}

// One empty cell of margin below the lowest support, so that the lattice starts outside the surface.
Lattice make_lattice(const BlobGroup& group, double cell_size) {
    check_cell_size(cell_size);
    Vec3d lower(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                std::numeric_limits<double>::infinity());
    Vec3d upper = -lower;
    for (const Metacube& element : group.elements()) {
        const WorldBounds b = element.support_bounds();
        lower = min(lower, b.lower);
        upper = max(upper, b.upper);
    }
    Lattice lattice{lower - Vec3d(cell_size, cell_size, cell_size), cell_size};
    const double cells = max_component(upper - lattice.origin) / cell_size + 2 * kBrickCells;
    if (!(cells < double(kAxisLimit)))
        throw std::invalid_argument("cell_size: " + std::to_string(cell_size) + " needs " + std::to_string(cells) +
                                    " cells along an axis; the limit is " + std::to_string(kAxisLimit));
    return lattice;
}

// The bricks that overlap some element's support box, sorted by key. Throws std::invalid_argument when a cell
// size far too small for the supports would list more bricks than memory can hold.
std::vector<std::uint64_t> active_bricks(const BlobGroup& group, const Lattice& lattice) {
    constexpr double kMaxBrickEntries = double(1 << 26);  // 512 MiB of keys
    std::vector<std::uint64_t> bricks;
    for (const Metacube& element : group.elements()) {
        const WorldBounds b = element.support_bounds();
        const LatticePoint lo = lattice.cell_of(b.lower), hi = lattice.cell_of(b.upper);
        double entries = 1;
        for (int k = 0; k < 3; ++k) entries *= double(hi[k] / kBrickCells - lo[k] / kBrickCells + 1);
        if (double(bricks.size()) + entries > kMaxBrickEntries)
            throw std::invalid_argument("cell_size: " + std::to_string(lattice.cell) +
                                        " is too small for these elements (more than 2^26 bricks of 8^3 cells)");
        for (std::int64_t z = lo[2] / kBrickCells; z <= hi[2] / kBrickCells; ++z)
            for (std::int64_t y = lo[1] / kBrickCells; y <= hi[1] / kBrickCells; ++y)
                for (std::int64_t x = lo[0] / kBrickCells; x <= hi[0] / kBrickCells; ++x) bricks.push_back(pack({x, y, z}));
    }
    std::sort(bricks.begin(), bricks.end());
    bricks.erase(std::unique(bricks.begin(), bricks.end()), bricks.end());
    return bricks;
}

// The lattice edge between two corners of the cell at `cell`: the corner with fewer bits is the lower end.
EdgeKey edge_key(const LatticePoint& cell, const CutEdge& edge) {
    const int a = edge.inside_corner, b = edge.outside_corner;
    const int lower = (a & b) == a ? a : b, upper = lower == a ? b : a;
    const LatticePoint p{cell[0] + (lower & 1), cell[1] + ((lower >> 1) & 1), cell[2] + ((lower >> 2) & 1)};
    return (pack(p) << 3) | std::uint64_t(upper & ~lower);
}

// Samples the brick's (8+1)³ lattice points and cuts each of its cells.
std::vector<KeyedTriangle> cut_brick(std::uint64_t brick, const Lattice& lattice, const BlobGroup& field,
                                     double threshold) {
    constexpr int n = kBrickCells + 1;
    const LatticePoint b = unpack(brick);
    const LatticePoint base{b[0] * kBrickCells, b[1] * kBrickCells, b[2] * kBrickCells};
    std::array<bool, n * n * n> inside{};
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                inside[std::size_t((z * n + y) * n + x)] =
                    field.field(lattice.point({base[0] + x, base[1] + y, base[2] + z})) > threshold;

    std::vector<KeyedTriangle> triangles;
    std::array<CutTriangle, 2> cut;
    for (int z = 0; z < kBrickCells; ++z)
        for (int y = 0; y < kBrickCells; ++y)
            for (int x = 0; x < kBrickCells; ++x) {
                std::uint8_t corners = 0;
                for (int c = 0; c < 8; ++c)
                    if (inside[std::size_t(((z + (c >> 2)) * n + y + ((c >> 1) & 1)) * n + x + (c & 1))])
                        corners = std::uint8_t(corners | (1 << c));
                if (corners == 0 || corners == 0xFF) continue;
                const LatticePoint cell{base[0] + x, base[1] + y, base[2] + z};
                for (const auto& tetrahedron : kuhn_tetrahedra()) {
                    const int count = cut_tetrahedron(tetrahedron, corners, cut);
                    for (int t = 0; t < count; ++t) {
                        const CutTriangle& triangle = cut[std::size_t(t)];
                        triangles.push_back({edge_key(cell, triangle[0]), edge_key(cell, triangle[1]),
                                             edge_key(cell, triangle[2])});
                    }
                }
            }
    return triangles;
}

// Where F = T on the segment from `from` to `to` (one end inside, the other not), as a fraction of its length:
// regula falsi with the Illinois modification, which keeps the bracket and converges superlinearly on smooth
// fields and still shrinks the bracket on a hard cube's step.
double crossing_fraction(const BlobGroup& field, double threshold, const Vec3d& from, const Vec3d& to) {
    constexpr int kMaxSteps = 60;
    constexpr double kTolerance = 1e-7;  // of the edge length: below the float precision of the result
    double a = 0, b = 1;
    double fa = field.field(from) - threshold, fb = field.field(to) - threshold;
    int last_side = 0;
    double t = 0.5;
    for (int step = 0; step < kMaxSteps && b - a > kTolerance; ++step) {
        t = fa != fb ? (a * fb - b * fa) / (fb - fa) : 0.5 * (a + b);
        if (!(t > a && t < b)) t = 0.5 * (a + b);
        const double ft = field.field(from + (to - from) * t) - threshold;
        if (ft == 0) break;
        if ((ft > 0) == (fa > 0)) {
            a = t, fa = ft;
            if (last_side == -1) fb *= 0.5;
            last_side = -1;
        } else {
            b = t, fb = ft;
            if (last_side == 1) fa *= 0.5;
            last_side = 1;
        }
    }
    return t;
}

struct SurfaceVertex {
    Vec3f position, normal;
};

SurfaceVertex place_vertex(EdgeKey key, const Lattice& lattice, const BlobGroup& field, double threshold) {
    const LatticePoint lower = unpack(key >> 3);
    const int direction = int(key & 7);
    const LatticePoint upper{lower[0] + (direction & 1), lower[1] + ((direction >> 1) & 1),
                             lower[2] + ((direction >> 2) & 1)};
    const Vec3d from = lattice.point(lower), to = lattice.point(upper);
    const Vec3d position = from + (to - from) * crossing_fraction(field, threshold, from, to);
    const Vec3d gradient = field.gradient(position);
    const double norm = length(gradient);
    if (norm > 0 && std::isfinite(norm)) return {Vec3f(position), Vec3f(-gradient / norm)};
    // Hard cubes have no gradient (a step): fall back to the edge, pointed from its inside end to its outside.
    const bool upper_inside = field.field(to) > threshold;
    return {Vec3f(position), Vec3f(normalize(upper_inside ? from - to : to - from))};
}

}  // namespace

double cell_size_for_smallest_element(const BlobGroup& group, double cells_per_radius) {
    if (!(std::isfinite(cells_per_radius) && cells_per_radius > 0))
        throw std::invalid_argument("cells_per_radius: must be finite and > 0, got " + std::to_string(cells_per_radius));
    double smallest = std::numeric_limits<double>::infinity();
    for (const Metacube& element : group.elements()) {
        const WorldBounds b = element.support_bounds();
        smallest = std::min(smallest, 0.5 * max_component(b.upper - b.lower));
    }
    return smallest / cells_per_radius;
}

TriangleMeshData polygonize(const BlobGroup& group, const PolygonizeSettings& settings) {
    TriangleMeshData mesh;
    if (group.elements().empty()) return mesh;
    const Lattice lattice = make_lattice(group, settings.cell_size);
    const BlobGroup& field = group;
    const double threshold = group.threshold();

    const std::vector<std::uint64_t> bricks = active_bricks(group, lattice);
    std::vector<std::vector<KeyedTriangle>> per_brick(bricks.size());
    parallel_for(std::size_t(0), bricks.size(),
                 [&](std::size_t i) { per_brick[i] = cut_brick(bricks[i], lattice, field, threshold); });

    std::vector<KeyedTriangle> triangles;
    for (auto& list : per_brick) {
        triangles.insert(triangles.end(), list.begin(), list.end());
        std::vector<KeyedTriangle>().swap(list);
    }
    // Vertex welding: one vertex per distinct lattice edge, numbered in key order.
    std::vector<EdgeKey> edges;
    edges.reserve(3 * triangles.size());
    for (const KeyedTriangle& t : triangles) edges.insert(edges.end(), t.begin(), t.end());
    parallel_sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    mesh.triangles.resize(triangles.size());
    parallel_for(std::size_t(0), triangles.size(), [&](std::size_t i) {
        for (int k = 0; k < 3; ++k) {
            const auto found = std::lower_bound(edges.begin(), edges.end(), triangles[i][std::size_t(k)]);
            mesh.triangles[i][std::size_t(k)] = std::uint32_t(found - edges.begin());
        }
    });
    mesh.positions.resize(edges.size());
    mesh.normals.resize(edges.size());
    parallel_for(std::size_t(0), edges.size(), [&](std::size_t i) {
        const SurfaceVertex vertex = place_vertex(edges[i], lattice, field, threshold);
        mesh.positions[i] = vertex.position;
        mesh.normals[i] = vertex.normal;
    });
    return mesh;
}

}  // namespace isotrace
