#include "geometry/polygonize/mesh_topology.h"

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include "renderer/core/parallel_sort.h"

namespace isotrace {

bool is_closed_and_consistently_oriented(const TriangleMeshData& mesh) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> directed;
    directed.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) directed.emplace_back(t[std::size_t(k)], t[std::size_t((k + 1) % 3)]);
    std::sort(directed.begin(), directed.end());
    if (std::adjacent_find(directed.begin(), directed.end()) != directed.end()) return false;
    return std::all_of(directed.begin(), directed.end(), [&](const auto& edge) {
        return std::binary_search(directed.begin(), directed.end(), std::make_pair(edge.second, edge.first));
    });
}

double signed_volume(const TriangleMeshData& mesh) {
    double volume = 0;
    for (const auto& t : mesh.triangles) {
        const Vec3d p0(mesh.positions[t[0]]), p1(mesh.positions[t[1]]), p2(mesh.positions[t[2]]);
        volume += dot(p0, cross(p1, p2));
    }
    return volume / 6;
}

std::size_t connected_components(const TriangleMeshData& mesh) {
    std::vector<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto root = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const auto& t : mesh.triangles) {
        parent[root(t[1])] = root(t[0]);
        parent[root(t[2])] = root(t[0]);
    }
    std::vector<std::uint32_t> roots;
    roots.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) roots.push_back(root(t[0]));
    std::sort(roots.begin(), roots.end());
    return std::size_t(std::unique(roots.begin(), roots.end()) - roots.begin());
}

namespace {

// Each triangle side as (smaller vertex << 32 | larger vertex), sorted: integers, so that they sort in parallel.
std::vector<std::uint64_t> undirected_edges(const TriangleMeshData& mesh) {
    std::vector<std::uint64_t> edges;
    edges.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
            edges.push_back(std::uint64_t(std::min(a, b)) << 32 | std::max(a, b));
        }
    parallel_sort(edges.begin(), edges.end());
    return edges;
}

}  // namespace

EdgeUse edge_use(const TriangleMeshData& mesh) {
    const auto edges = undirected_edges(mesh);
    EdgeUse use;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i == 1) ++use.boundary;
        if (j - i > 2) ++use.over_shared;
        i = j;
    }
    return use;
}

long euler_characteristic(const TriangleMeshData& mesh) {
    auto edges = undirected_edges(mesh);
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    std::vector<std::uint32_t> used;
    for (const auto& t : mesh.triangles) used.insert(used.end(), t.begin(), t.end());
    std::sort(used.begin(), used.end());
    const auto vertices = std::unique(used.begin(), used.end()) - used.begin();
    return long(vertices) - long(edges.size()) + long(mesh.triangles.size());
}

bool is_closed_two_manifold(const TriangleMeshData& mesh) {
    if (!is_closed_and_consistently_oriented(mesh)) return false;
    // Around vertex v, triangle (v, a, b) links a to b; a closed oriented mesh gives each a one successor, and the
    // links must form a single cycle.
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> links(mesh.positions.size());
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            links[t[std::size_t(k)]].emplace_back(t[std::size_t((k + 1) % 3)], t[std::size_t((k + 2) % 3)]);
    for (auto& link : links) {
        if (link.empty()) continue;
        std::sort(link.begin(), link.end());
        std::size_t steps = 0;
        std::uint32_t at = link.front().first;
        do {
            const auto next = std::lower_bound(link.begin(), link.end(), std::make_pair(at, std::uint32_t(0)));
            if (next == link.end() || next->first != at) return false;
            at = next->second;
            ++steps;
        } while (at != link.front().first && steps <= link.size());
        if (steps != link.size()) return false;
    }
    return true;
}

}  // namespace isotrace
