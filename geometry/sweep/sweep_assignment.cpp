#include "geometry/sweep/sweep_assignment.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <queue>
#include <utility>

namespace isotrace {
namespace {

bool inside(const std::optional<VertexBinding>& b) { return b && b->d <= 0; }

using Entry = std::pair<double, std::uint32_t>;
using Front = std::priority_queue<Entry, std::vector<Entry>, std::greater<>>;

// Multi-source Dijkstra over the mesh's edges from the vertices in `front` (their `distance` set), up to `limit`:
// `may_enter(v, w)` says whether the search may go on from v to w, `entered(v, w)` hears that w got nearer
// through v. Each vertex is settled once, so the loop is bounded by the edges.
template <class MayEnter, class Entered>
void grow(const TriangleMeshData& mesh, const VertexNeighbours& next, Front& front, std::vector<double>& distance,
          double limit, MayEnter may_enter, Entered entered) {
    while (!front.empty()) {
        const auto [d, v] = front.top();
        front.pop();
        if (d > distance[v]) continue;
        for (const std::uint32_t w : next[v]) {
            const double through = d + length(Vec3d(mesh.positions[w]) - Vec3d(mesh.positions[v]));
            if (through >= distance[w] || through >= limit || !may_enter(v, w)) continue;
            distance[w] = through;
            entered(v, w);
            front.push({through, w});
        }
    }
}

}  // namespace

VertexNeighbours vertex_neighbours(const TriangleMeshData& mesh) {
    std::vector<std::vector<std::uint32_t>> next(mesh.positions.size());
    auto join = [&](std::uint32_t a, std::uint32_t b) {
        next[a].push_back(b);
        next[b].push_back(a);
    };
    for (const auto& t : mesh.triangles)
        for (std::size_t k = 0; k < 3; ++k) join(t[k], t[(k + 1) % 3]);
    std::map<std::array<float, 3>, std::uint32_t> first;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        const Vec3f& p = mesh.positions[v];
        const auto [at, fresh] = first.try_emplace({p.x, p.y, p.z}, v);
        if (!fresh) join(at->second, v);
    }
    return next;
}

std::vector<int> assign_sweeps(const TriangleMeshData& mesh, const VertexNeighbours& next, const SweepBindings& bindings,
                               const std::vector<int>& grouped) {
    const std::size_t count = mesh.positions.size();
    std::vector<int> owner(count, -1);
    std::vector<double> distance(count, INFINITY);
    Front front;
    for (std::uint32_t v = 0; v < count; ++v) {
        int only = grouped.empty() ? -1 : grouped[v];
        if (only < 0) {
            for (std::size_t s = 0; s < bindings.size(); ++s) {
                if (!inside(bindings[s][v])) continue;
                only = only < 0 ? int(s) : -2;  // −2: inside several
            }
        }
        if (only < 0) continue;
        owner[v] = only;
        distance[v] = 0;
        front.push({0, v});
    }
    grow(mesh, next, front, distance, INFINITY,
         [&](std::uint32_t v, std::uint32_t w) {
             return bindings[std::size_t(owner[v])][w] && (grouped.empty() || grouped[w] < 0);
         },
         [&](std::uint32_t v, std::uint32_t w) { owner[w] = owner[v]; });
    for (std::size_t v = 0; v < count; ++v) {
        if (owner[v] >= 0) continue;
        double deepest = INFINITY;
        for (std::size_t s = 0; s < bindings.size(); ++s) {
            const std::optional<VertexBinding>& b = bindings[s][v];
            if (!b) continue;
            const double u = b->radius > 0 ? 1 + b->d / b->radius : b->d;
            if (u < deepest) {
                deepest = u;
                owner[v] = int(s);
            }
        }
    }
    return owner;
}

std::vector<std::vector<SweepShare>> blend_sweeps(const TriangleMeshData& mesh, const VertexNeighbours& next,
                                                  const SweepBindings& bindings, const std::vector<int>& owner,
                                                  const std::vector<double>& widths) {
    const std::size_t count = mesh.positions.size();
    std::vector<std::vector<SweepShare>> shares(count);
    for (std::size_t v = 0; v < count; ++v)
        if (owner[v] >= 0) shares[v].push_back({owner[v], 1});
    std::vector<double> distance(count);
    for (std::size_t s = 0; s < bindings.size(); ++s) {
        // Distances from sweep s's vertices into the others' that s binds, up to its width: bounded by the edges.
        std::fill(distance.begin(), distance.end(), INFINITY);
        Front front;
        for (std::uint32_t v = 0; v < count; ++v)
            if (owner[v] == int(s)) {
                distance[v] = 0;
                front.push({0, v});
            }
        grow(mesh, next, front, distance, widths[s],
             [&](std::uint32_t, std::uint32_t w) { return owner[w] >= 0 && owner[w] != int(s) && inside(bindings[s][w]); },
             [](std::uint32_t, std::uint32_t) {});
        for (std::size_t v = 0; v < count; ++v) {
            if (owner[v] < 0 || owner[v] == int(s) || !std::isfinite(distance[v])) continue;
            const double width = std::min(widths[s], widths[std::size_t(owner[v])]);
            if (distance[v] < width) shares[v].push_back({int(s), 1 - distance[v] / width});
        }
    }
    for (std::vector<SweepShare>& share : shares) {
        double total = 0;
        for (const SweepShare& s : share) total += s.weight;
        for (SweepShare& s : share) s.weight /= total;
    }
    return shares;
}

}  // namespace isotrace
