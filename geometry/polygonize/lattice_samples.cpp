#include "geometry/polygonize/lattice_samples.h"

#include <algorithm>
#include <cmath>

#include "geometry/polygonize/cube_cycles.h"
#include "renderer/core/parallel_for.h"

namespace isotrace {
namespace {

// Cells where the descent hands over to parallel tasks (8³ subtrees at most).
constexpr int kTaskLevel = 3;

void descend(const ImplicitField& field, const Lattice& lattice, int level, const LatticeIndex& cell,
             std::vector<LatticeKey>& out) {
    if (!lattice.may_hold_surface(field, level, cell)) return;
    if (level == lattice.depth()) {
        out.push_back(lattice_key(cell));
        return;
    }
    for (int child = 0; child < 8; ++child)
        descend(field, lattice, level + 1,
                {2 * cell[0] + (child & 1), 2 * cell[1] + ((child >> 1) & 1), 2 * cell[2] + ((child >> 2) & 1)}, out);
}

std::vector<LatticeKey> candidate_cells(const ImplicitField& field, const Lattice& lattice) {
    const int task_level = std::min(kTaskLevel, lattice.depth());
    std::vector<LatticeIndex> tasks;
    const int n = 1 << task_level;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) tasks.push_back({i, j, k});
    std::vector<std::vector<LatticeKey>> found(tasks.size());
    parallel_for(std::size_t(0), tasks.size(), [&](std::size_t t) {
        // The ancestors were not tested: a task's first test covers them (a cell can only hold surface its
        // ancestors may hold).
        descend(field, lattice, task_level, tasks[t], found[t]);
    });
    std::vector<LatticeKey> cells;
    for (const auto& part : found) cells.insert(cells.end(), part.begin(), part.end());
    std::sort(cells.begin(), cells.end());
    return cells;
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
    const std::vector<LatticeKey> candidates = candidate_cells(field, lattice);
    samples.candidate_cells = candidates.size();

    std::vector<LatticeKey>& corners = samples.corners;
    corners.reserve(candidates.size() * 8);
    for (LatticeKey key : candidates)
        for (int c = 0; c < 8; ++c) corners.push_back(lattice_key(lattice.canonical_corner(corner_of(lattice_index(key), c))));
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    std::vector<double> values(corners.size());
    samples.corner_inside.resize(corners.size());
    parallel_for(std::size_t(0), corners.size(), [&](std::size_t i) {
        const LatticeIndex c = lattice_index(corners[i]);
        values[i] = field.value(lattice.position(Vec3d(c[0], c[1], c[2])));
        samples.corner_inside[i] = values[i] < 0;
    });
    const auto value_at = [&](const LatticeIndex& corner) {
        return values[position_of(corners, lattice_key(lattice.canonical_corner(corner)))];
    };

    std::vector<std::uint8_t> patterns(candidates.size());
    parallel_for(std::size_t(0), candidates.size(), [&](std::size_t i) {
        const LatticeIndex cell = lattice_index(candidates[i]);
        std::uint8_t inside = 0;
        for (int c = 0; c < 8; ++c)
            if (value_at(corner_of(cell, c)) < 0) inside |= std::uint8_t(1 << c);
        patterns[i] = inside;
    });
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (patterns[i] != 0 && patterns[i] != 255) {
            samples.cells.push_back(candidates[i]);
            samples.inside.push_back(patterns[i]);
        }

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
