#include "geometry/polygonize/lattice_samples.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/polygonize/cube_cycles.h"
#include "renderer/core/parallel_for.h"
#include "renderer/core/parallel_sort.h"

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

LatticeIndex corner_of(const LatticeIndex& cell, int corner) {
    return {cell[0] + (corner & 1), cell[1] + ((corner >> 1) & 1), cell[2] + ((corner >> 2) & 1)};
}

std::size_t position_of(const std::vector<LatticeKey>& keys, LatticeKey key) {
    return std::size_t(std::lower_bound(keys.begin(), keys.end(), key) - keys.begin());
}

// The point at parameter t ∈ [0, 1] of the lattice edge from `corner` along `axis` (on a spherical lattice an edge
// in θ or φ is an arc).
Vec3d point_on_edge(const Lattice& lattice, const LatticeIndex& corner, int axis, double t) {
    Vec3d step;
    step[axis] = 1;
    return lattice.position(Vec3d(corner[0], corner[1], corner[2]) + step * t);
}

// The search of edge_crossing along one edge, a field value at a time, so that the edges of a brick can search
// side by side with one batch of values per step: regula falsi (Illinois) in t, safeguarded by bisection.
class EdgeRootSearch {
public:
    EdgeRootSearch(double lower_value, double upper_value) : fa_(lower_value), fb_(upper_value) {}

    bool searching() const { return !exact_ && iterations_ < 64 && b_ - a_ > 1e-9; }
    // Where the next value is wanted; once the search is over, the crossing.
    double next() const {
        if (exact_) return a_;
        const double t = (a_ * fb_ - b_ * fa_) / (fb_ - fa_);
        return t > a_ && t < b_ ? t : (a_ + b_) / 2;
    }
    void take(double t, double ft) {
        ++iterations_;
        if (ft == 0) {
            exact_ = true;
            a_ = t;
        } else if ((ft < 0) == (fa_ < 0)) {
            a_ = t;
            fa_ = ft;
            if (last_side_ < 0) fb_ /= 2;  // Illinois: the stale end's weight halves, so both ends move
            last_side_ = -1;
        } else {
            b_ = t;
            fb_ = ft;
            if (last_side_ > 0) fa_ /= 2;
            last_side_ = 1;
        }
    }

private:
    double a_ = 0, b_ = 1, fa_, fb_;
    int last_side_ = 0, iterations_ = 0;
    bool exact_ = false;
};

// What one brick contributes: its cells with corners of both signs, their corners and cut edges, and the Hermite
// data of the cut edges it owns — those whose canonical lower corner lies in the brick's half-open range, so that
// both ends are among its samples and no other brick owns them.
struct BrickSamples {
    std::vector<LatticeKey> cells;  // ascending
    std::vector<std::uint8_t> inside;
    std::vector<LatticeKey> corners;  // canonical key << 1 | inside, of the cells' corners
    std::vector<LatticeKey> edges;    // every cut edge of the cells
    std::vector<LatticeKey> owned;
    std::vector<Vec3d> crossings, gradients;
    std::vector<std::uint8_t> lower_inside;
};

struct OwnedEdge {
    LatticeIndex corner;
    int axis;
    EdgeRootSearch search;
};

// The crossings of the owned edges, all searching at once.
void find_crossings(const ImplicitField& field, const Lattice& lattice, std::vector<OwnedEdge>& edges) {
    std::vector<std::size_t> active(edges.size());
    for (std::size_t i = 0; i < edges.size(); ++i) active[i] = i;
    std::vector<double> ts, values;
    std::vector<Vec3d> points;
    while (true) {
        active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t i) { return !edges[i].search.searching(); }),
                     active.end());
        if (active.empty()) return;
        ts.clear();
        points.clear();
        for (std::size_t i : active) {
            ts.push_back(edges[i].search.next());
            points.push_back(point_on_edge(lattice, edges[i].corner, edges[i].axis, ts.back()));
        }
        values.resize(points.size());
        field.values(points, values);
        for (std::size_t k = 0; k < active.size(); ++k) edges[active[k]].search.take(ts[k], values[k]);
    }
}

BrickSamples sample_brick(const ImplicitField& field, const Lattice& lattice, const LatticeIndex& brick, int size) {
    const int m = size + 1;  // corners along each axis
    const auto at = [m](const LatticeIndex& local) { return std::size_t((local[2] * m + local[1]) * m + local[0]); };
    const LatticeIndex base = {brick[0] * size, brick[1] * size, brick[2] * size};
    std::vector<LatticeKey> keys(std::size_t(m) * m * m);
    std::vector<Vec3d> points(keys.size());
    for (int z = 0; z < m; ++z)
        for (int y = 0; y < m; ++y)
            for (int x = 0; x < m; ++x) {
                const LatticeIndex c = lattice.canonical_corner({base[0] + x, base[1] + y, base[2] + z});
                keys[at({x, y, z})] = lattice_key(c);
                points[at({x, y, z})] = lattice.position(Vec3d(c[0], c[1], c[2]));
            }
    std::vector<double> values(keys.size());
    field.values(points, values);

    BrickSamples result;
    std::vector<std::uint8_t> corner_used(keys.size()), edge_seen(keys.size() * 3);
    std::vector<OwnedEdge> owned;
    for (int z = 0; z < size; ++z)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const LatticeIndex local = {x, y, z};
                std::uint8_t inside = 0;
                for (int c = 0; c < 8; ++c)
                    if (values[at(corner_of(local, c))] < 0) inside |= std::uint8_t(1 << c);
                if (inside == 0 || inside == 255) continue;
                result.cells.push_back(lattice_key({base[0] + x, base[1] + y, base[2] + z}));
                result.inside.push_back(inside);
                for (int c = 0; c < 8; ++c) corner_used[at(corner_of(local, c))] = 1;
                for (int e = 0; e < 12; ++e) {
                    const auto ends = cube_edge_corners(e);
                    if (((inside >> ends[0]) & 1) == ((inside >> ends[1]) & 1)) continue;
                    const int axis = e / 4;
                    const LatticeIndex lower = corner_of(local, ends[0]);
                    if (std::exchange(edge_seen[at(lower) * 3 + std::size_t(axis)], 1)) continue;
                    const LatticeIndex global = {base[0] + lower[0], base[1] + lower[1], base[2] + lower[2]};
                    LatticeIndex corner = global;
                    if (!lattice.canonical_edge(corner, axis)) continue;
                    result.edges.push_back(edge_key(corner, axis));
                    if (corner != global || lower[0] == size || lower[1] == size || lower[2] == size) continue;
                    LatticeIndex upper = lower;
                    ++upper[axis];
                    owned.push_back({corner, axis, EdgeRootSearch(values[at(lower)], values[at(upper)])});
                    result.owned.push_back(result.edges.back());
                    result.lower_inside.push_back(values[at(lower)] < 0);
                }
            }
    for (std::size_t i = 0; i < keys.size(); ++i)
        if (corner_used[i]) result.corners.push_back(keys[i] << 1 | LatticeKey(values[i] < 0));

    find_crossings(field, lattice, owned);
    for (const OwnedEdge& edge : owned) {
        result.crossings.push_back(point_on_edge(lattice, edge.corner, edge.axis, edge.search.next()));
        result.gradients.push_back(field.gradient(result.crossings.back()));
    }
    // Held until the merge, for every brick at once: no room to spare.
    for (auto* keys : {&result.cells, &result.corners, &result.edges, &result.owned}) keys->shrink_to_fit();
    result.inside.shrink_to_fit();
    result.lower_inside.shrink_to_fit();
    return result;
}

// Sorted and without repeats.
void sort_unique(std::vector<LatticeKey>& keys) {
    parallel_sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
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
    EdgeRootSearch search(lower_value, upper_value);
    while (search.searching()) {
        const double t = search.next();
        search.take(t, field.value(point_on_edge(lattice, corner, axis, t)));
    }
    return point_on_edge(lattice, corner, axis, search.next());
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

    // Merged in key order, whatever order the bricks were done in. Corners and edges on a face between bricks
    // come from each (a corner with the same value: the same point).
    for (const BrickSamples& part : parts) {
        samples.cells.insert(samples.cells.end(), part.cells.begin(), part.cells.end());
        samples.corners.insert(samples.corners.end(), part.corners.begin(), part.corners.end());
        samples.edges.insert(samples.edges.end(), part.edges.begin(), part.edges.end());
    }
    sort_unique(samples.cells);
    sort_unique(samples.corners);
    sort_unique(samples.edges);
    samples.corner_inside.resize(samples.corners.size());
    for (std::size_t i = 0; i < samples.corners.size(); ++i) {
        samples.corner_inside[i] = samples.corners[i] & 1;
        samples.corners[i] >>= 1;
    }
    const std::size_t count = samples.edges.size();
    samples.inside.resize(samples.cells.size());
    samples.crossings.resize(count);
    samples.gradients.resize(count);
    samples.lower_inside.resize(count);
    std::vector<std::uint8_t> found(count);
    parallel_for(std::size_t(0), parts.size(), [&](std::size_t b) {
        BrickSamples& part = parts[b];
        for (std::size_t i = 0; i < part.cells.size(); ++i) samples.inside[position_of(samples.cells, part.cells[i])] = part.inside[i];
        for (std::size_t i = 0; i < part.owned.size(); ++i) {
            const std::size_t e = position_of(samples.edges, part.owned[i]);
            samples.crossings[e] = part.crossings[i];
            samples.gradients[e] = part.gradients[i];
            samples.lower_inside[e] = part.lower_inside[i];
            found[e] = 1;
        }
        part = {};
    });
    // Cut edges no brick owns (a spherical lattice's south polar axis, whose lower corners are past the last θ
    // index): sampled here, at the same points.
    parallel_for(std::size_t(0), count, [&](std::size_t e) {
        if (found[e]) return;
        const int axis = int(samples.edges[e] & 3);
        const LatticeIndex corner = lattice_index(samples.edges[e] >> 2);
        LatticeIndex upper = corner;
        ++upper[axis];
        const auto value_at = [&](const LatticeIndex& c) {
            const LatticeIndex canonical = lattice.canonical_corner(c);
            return field.value(lattice.position(Vec3d(canonical[0], canonical[1], canonical[2])));
        };
        const double lower_value = value_at(corner), upper_value = value_at(upper);
        samples.crossings[e] = edge_crossing(field, lattice, corner, axis, lower_value, upper_value);
        samples.gradients[e] = field.gradient(samples.crossings[e]);
        samples.lower_inside[e] = lower_value < 0;
    });
    return samples;
}

}  // namespace isotrace
