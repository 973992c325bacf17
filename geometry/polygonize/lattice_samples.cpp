#include "geometry/polygonize/lattice_samples.h"

#include <algorithm>
#include <cmath>

#include "geometry/polygonize/cube_cycles.h"
#include "renderer/core/parallel_for.h"

namespace isotrace {
namespace {

// Levels below a brick: the descent stops at bricks of 8³ finest cells, whose 9³ corners are sampled in one batch
// (ImplicitField::values). Testing each finest cell instead (a blob cloud's Lipschitz test keeps over ten times
// the cells the surface cuts) cost more than sampling them all, and the corners shared by neighbouring cells are
// then evaluated once per brick, not looked up in a lattice-wide table.
constexpr int kBrickLevels = 3;
// Bricks where the descent hands over to parallel tasks (8³ subtrees at most).
constexpr int kTaskLevel = 3;

void descend(const ImplicitField& field, const Lattice& lattice, int level, int brick_level, const LatticeIndex& cell,
             std::vector<LatticeKey>& out) {
    if (!lattice.may_hold_surface(field, level, cell)) return;
    if (level == brick_level) {
        out.push_back(lattice_key(cell));
        return;
    }
    for (int child = 0; child < 8; ++child)
        descend(field, lattice, level + 1, brick_level,
                {2 * cell[0] + (child & 1), 2 * cell[1] + ((child >> 1) & 1), 2 * cell[2] + ((child >> 2) & 1)}, out);
}

// The bricks (octree nodes of `brick_level`) that may hold surface, sorted.
std::vector<LatticeKey> surface_bricks(const ImplicitField& field, const Lattice& lattice, int brick_level) {
    const int task_level = std::min(kTaskLevel, brick_level);
    std::vector<LatticeIndex> tasks;
    const int n = 1 << task_level;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) tasks.push_back({i, j, k});
    std::vector<std::vector<LatticeKey>> found(tasks.size());
    parallel_for(std::size_t(0), tasks.size(), [&](std::size_t t) {
        // The ancestors were not tested: a task's first test covers them (a cell can only hold surface its
        // ancestors may hold).
        descend(field, lattice, task_level, brick_level, tasks[t], found[t]);
    });
    std::vector<LatticeKey> bricks;
    for (const auto& part : found) bricks.insert(bricks.end(), part.begin(), part.end());
    std::sort(bricks.begin(), bricks.end());
    return bricks;
}

// What one brick contributes: its cells with corners of both signs and the values at their corners.
struct BrickSamples {
    std::vector<std::pair<LatticeKey, std::uint8_t>> cells;  // key, inside pattern; ascending
    std::vector<std::pair<LatticeKey, double>> corners;      // canonical key, value
};

BrickSamples sample_brick(const ImplicitField& field, const Lattice& lattice, const LatticeIndex& brick, int size) {
    const int m = size + 1;  // corners along each axis
    const auto at = [m](int x, int y, int z) { return std::size_t((z * m + y) * m + x); };
    const LatticeIndex base = {brick[0] * size, brick[1] * size, brick[2] * size};
    std::vector<LatticeKey> keys(std::size_t(m) * m * m);
    std::vector<Vec3d> points(keys.size());
    for (int z = 0; z < m; ++z)
        for (int y = 0; y < m; ++y)
            for (int x = 0; x < m; ++x) {
                const LatticeIndex c = lattice.canonical_corner({base[0] + x, base[1] + y, base[2] + z});
                keys[at(x, y, z)] = lattice_key(c);
                points[at(x, y, z)] = lattice.position(Vec3d(c[0], c[1], c[2]));
            }
    std::vector<double> values(keys.size());
    field.values(points, values);

    BrickSamples result;
    std::vector<std::uint8_t> used(keys.size());
    for (int z = 0; z < size; ++z)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                std::uint8_t inside = 0;
                for (int c = 0; c < 8; ++c)
                    if (values[at(x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1))] < 0) inside |= std::uint8_t(1 << c);
                if (inside == 0 || inside == 255) continue;
                result.cells.emplace_back(lattice_key({base[0] + x, base[1] + y, base[2] + z}), inside);
                for (int c = 0; c < 8; ++c) used[at(x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1))] = 1;
            }
    for (std::size_t i = 0; i < keys.size(); ++i)
        if (used[i]) result.corners.emplace_back(keys[i], values[i]);
    return result;
}

LatticeIndex corner_of(const LatticeIndex& cell, int corner) {
    return {cell[0] + (corner & 1), cell[1] + ((corner >> 1) & 1), cell[2] + ((corner >> 2) & 1)};
}

std::size_t position_of(const std::vector<LatticeKey>& keys, LatticeKey key) {
    return std::size_t(std::lower_bound(keys.begin(), keys.end(), key) - keys.begin());
}

}  // namespace

std::optional<std::size_t> LatticeSamples::cell(LatticeKey key) const {
    const std::size_t i = position_of(cells, key);
    if (i == cells.size() || cells[i] != key) return std::nullopt;
    return i;
}

std::optional<std::size_t> LatticeSamples::edge(LatticeKey key) const {
    const std::size_t i = position_of(edges, key);
    if (i == edges.size() || edges[i] != key) return std::nullopt;
    return i;
}

std::optional<std::size_t> LatticeSamples::corner(LatticeKey key) const {
    const std::size_t i = position_of(corners, key);
    if (i == corners.size() || corners[i] != key) return std::nullopt;
    return i;
}

Vec3d edge_crossing(const ImplicitField& field, const Lattice& lattice, const LatticeIndex& corner, int axis,
                    double lower_value, double upper_value) {
    const Vec3d start(corner[0], corner[1], corner[2]);
    Vec3d step;
    step[axis] = 1;
    const auto at = [&](double t) { return lattice.position(start + step * t); };
    double a = 0, b = 1, fa = lower_value, fb = upper_value;
    int last_side = 0;
    for (int iteration = 0; iteration < 64 && b - a > 1e-9; ++iteration) {
        double t = (a * fb - b * fa) / (fb - fa);
        if (!(t > a && t < b)) t = (a + b) / 2;
        const double ft = field.value(at(t));
        if (ft == 0) return at(t);
        if ((ft < 0) == (fa < 0)) {
            a = t;
            fa = ft;
            if (last_side < 0) fb /= 2;  // Illinois: the stale end's weight halves, so both ends move
            last_side = -1;
        } else {
            b = t;
            fb = ft;
            if (last_side > 0) fa /= 2;
            last_side = 1;
        }
    }
    const double t = (a * fb - b * fa) / (fb - fa);
    return at(t > a && t < b ? t : (a + b) / 2);
}

LatticeSamples sample_lattice(const ImplicitField& field, const Lattice& lattice) {
    LatticeSamples samples;
    const int brick_level = std::max(0, lattice.depth() - kBrickLevels);
    const int brick_size = 1 << (lattice.depth() - brick_level);
    const std::vector<LatticeKey> bricks = surface_bricks(field, lattice, brick_level);
    samples.candidate_cells = bricks.size() * std::size_t(brick_size) * brick_size * brick_size;
    samples.corner_samples = bricks.size() * std::size_t(brick_size + 1) * (brick_size + 1) * (brick_size + 1);
    std::vector<BrickSamples> parts(bricks.size());
    parallel_for(std::size_t(0), bricks.size(), [&](std::size_t b) {
        parts[b] = sample_brick(field, lattice, lattice_index(bricks[b]), brick_size);
    });

    // Merged in key order, whatever order the bricks were done in. A corner on a face between bricks was sampled
    // by each, to the same value (the same point).
    std::vector<std::pair<LatticeKey, std::uint8_t>> cells;
    std::vector<std::pair<LatticeKey, double>> corners;
    for (BrickSamples& part : parts) {
        cells.insert(cells.end(), part.cells.begin(), part.cells.end());
        corners.insert(corners.end(), part.corners.begin(), part.corners.end());
        part = {};
    }
    std::sort(cells.begin(), cells.end());
    std::sort(corners.begin(), corners.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    corners.erase(std::unique(corners.begin(), corners.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
                  corners.end());
    for (const auto& [key, inside] : cells) {
        samples.cells.push_back(key);
        samples.inside.push_back(inside);
    }
    std::vector<double> values;
    for (const auto& [key, value] : corners) {
        samples.corners.push_back(key);
        samples.corner_inside.push_back(value < 0);
        values.push_back(value);
    }
    const auto value_at = [&](const LatticeIndex& corner) {
        return values[position_of(samples.corners, lattice_key(lattice.canonical_corner(corner)))];
    };

    for (std::size_t i = 0; i < samples.cells.size(); ++i) {
        const LatticeIndex cell = lattice_index(samples.cells[i]);
        for (int e = 0; e < 12; ++e) {
            const auto ends = cube_edge_corners(e);
            if (((samples.inside[i] >> ends[0]) & 1) == ((samples.inside[i] >> ends[1]) & 1)) continue;
            LatticeIndex corner = corner_of(cell, ends[0]);
            if (lattice.canonical_edge(corner, e / 4)) samples.edges.push_back(edge_key(corner, e / 4));
        }
    }
    std::sort(samples.edges.begin(), samples.edges.end());
    samples.edges.erase(std::unique(samples.edges.begin(), samples.edges.end()), samples.edges.end());

    const std::size_t count = samples.edges.size();
    samples.crossings.resize(count);
    samples.gradients.resize(count);
    samples.lower_inside.resize(count);
    parallel_for(std::size_t(0), count, [&](std::size_t i) {
        const int axis = int(samples.edges[i] & 3);
        const LatticeIndex corner = lattice_index(samples.edges[i] >> 2);
        LatticeIndex upper = corner;
        ++upper[axis];
        const double lower_value = value_at(corner), upper_value = value_at(upper);
        samples.crossings[i] = edge_crossing(field, lattice, corner, axis, lower_value, upper_value);
        samples.gradients[i] = field.gradient(samples.crossings[i]);
        samples.lower_inside[i] = lower_value < 0;
    });
    return samples;
}

}  // namespace isotrace
