#include "geometry/polygonize/mesh_topology.h"

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

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

}  // namespace isotrace
