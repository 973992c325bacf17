#include "geometry/mesh/mesh_quality.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

#include "geometry/mesh/mesh_crossing_scene.h"
#include "geometry/mesh/triangle_mesh_shape.h"
#include "renderer/core/parallel_for.h"
#include "renderer/embree/embree_device.h"

namespace isotrace {
namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;

std::vector<Edge> unique_edges(const TriangleMeshData& mesh) {
    std::vector<Edge> edges;
    edges.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) edges.push_back(std::minmax(t[std::size_t(k)], t[std::size_t((k + 1) % 3)]));
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

Vec3d face_normal(const TriangleMeshData& mesh, const std::array<std::uint32_t, 3>& t) {
    const Vec3d p0(mesh.positions[t[0]]), p1(mesh.positions[t[1]]), p2(mesh.positions[t[2]]);
    return cross(p1 - p0, p2 - p0);
}

// Edges crossing a triangle that has neither of their end points (compared by position, so that vertices
// repeated at seams count as shared). Crossings at the edge's very ends are contacts, not intersections.
std::size_t crossing_edges(const TriangleMeshData& mesh, const std::vector<Edge>& edges) {
    TriangleMeshShape shape(mesh);
    const MeshCrossingScene scene(embree_device(), shape.create_geometry(embree_device()));
    check_embree("building the mesh for the self-intersection test");
    std::atomic<std::size_t> count = 0;
    parallel_for(std::size_t(0), edges.size(), [&](std::size_t e) {
        const Vec3f a = mesh.positions[edges[e].first], b = mesh.positions[edges[e].second];
        std::vector<MeshCrossing> crossings;
        scene.crossings(Vec3d(a), Vec3d(b) - Vec3d(a), 1, crossings);
        for (const MeshCrossing& c : crossings) {
            if (c.t <= 1e-4 || c.t >= 1 - 1e-4) continue;
            const auto& t = mesh.triangles[c.triangle];
            const bool touches = std::any_of(t.begin(), t.end(), [&](std::uint32_t v) {
                return mesh.positions[v] == a || mesh.positions[v] == b;
            });
            if (!touches) {
                ++count;
                return;
            }
        }
    });
    return count;
}

}  // namespace

MeshQuality measure_mesh_quality(const TriangleMeshData& before, const TriangleMeshData& after) {
    if (before.triangles != after.triangles || before.positions.size() != after.positions.size())
        throw std::invalid_argument("mesh quality: the two meshes do not have the same vertices and triangles");
    MeshQuality quality;
    for (const auto& t : before.triangles)
        if (dot(face_normal(before, t), face_normal(after, t)) < 0) ++quality.flipped_faces;
    const std::vector<Edge> edges = unique_edges(before);
    for (const auto& [i, j] : edges) {
        const double was = length(Vec3d(before.positions[i]) - Vec3d(before.positions[j]));
        if (was == 0) continue;
        const double stretch = length(Vec3d(after.positions[i]) - Vec3d(after.positions[j])) / was;
        quality.max_edge_stretch = std::max(quality.max_edge_stretch, stretch);
        if (stretch > MeshQuality::kStretchLimit) ++quality.stretched_edges;
    }
    quality.crossing_edges = crossing_edges(after, edges);
    quality.input_crossing_edges = crossing_edges(before, edges);
    return quality;
}

std::string describe(const MeshQuality& q) {
    char text[200];
    std::snprintf(text, sizeof(text), "%zu flipped faces, max edge stretch %.3g× (%zu edges > %g×), %zu self-intersecting edges (input %zu)",
                  q.flipped_faces, q.max_edge_stretch, q.stretched_edges, MeshQuality::kStretchLimit, q.crossing_edges,
                  q.input_crossing_edges);
    return text;
}

}  // namespace isotrace
