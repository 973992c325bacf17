#pragma once
// Curved boundary loops for the patch tests.
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <vector>

#include "geometry/abm_patch/abm_patch.h"
#include "geometry/mesh/triangle_mesh_data.h"

namespace isotrace::abm_test {

inline std::shared_ptr<const SpaceCurve> bezier(std::vector<Vec3d> points) {
    return std::make_shared<const SpaceCurve>(SpaceCurve::bezier(std::move(points)));
}

inline PatchSide side(std::shared_ptr<const SpaceCurve> curve, bool reversed = false) {
    return {std::move(curve), reversed, "curve"};
}

// N cubic curves between the corners of a bumpy N-gon in space: corners on a circle with alternating heights,
// inner control points bulging outward and up. Closed: each curve ends where the next starts.
inline std::vector<PatchSide> curved_loop(int n) {
    std::vector<Vec3d> corners;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * k / n;
        corners.push_back({std::cos(a), std::sin(a), 0.2 * (k % 2) - 0.1 * k / n});
    }
    std::vector<PatchSide> sides;
    for (int k = 0; k < n; ++k) {
        const Vec3d a = corners[std::size_t(k)], b = corners[std::size_t((k + 1) % n)];
        const Vec3d out = 0.25 * (a + b) + Vec3d{0, 0, 0.3 + 0.05 * k};
        sides.push_back(side(bezier({a, a + (1.0 / 3) * (b - a) + out, a + (2.0 / 3) * (b - a) + 0.5 * out, b})));
    }
    return sides;
}

// A closed curved tetrahedron: four three-sided patches over six shared bulging curves, each patch's loop
// counter-clockwise seen from outside, so every curve is used once forwards and once backwards. With
// `copies`, every patch gets its own copy of each curve (as if written out inline), the later patches' copies
// shifted by `copy_offset` in their middle control points.
inline std::vector<AbmPatch> curved_tetrahedron(bool polygon_domains, double p = 1, bool copies = false,
                                                double copy_offset = 0) {
    const Vec3d v[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    std::map<std::pair<int, int>, std::shared_ptr<const SpaceCurve>> edges;
    auto edge = [&](int a, int b) -> PatchSide {
        const bool reversed = a > b;
        const auto key = std::make_pair(std::min(a, b), std::max(a, b));
        if (!edges.count(key) || copies) {
            const Vec3d p = v[key.first], q = v[key.second];
            const Vec3d bulge = 0.35 * normalize(p + q) + Vec3d{0, 0, edges.count(key) ? copy_offset : 0};
            edges[key] = bezier({p, (2.0 / 3) * p + (1.0 / 3) * q + bulge, (1.0 / 3) * p + (2.0 / 3) * q + bulge, q});
        }
        return {edges[key], reversed, "edge"};
    };
    const int faces[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    std::vector<AbmPatch> patches;
    for (const auto& f : faces)
        patches.emplace_back(polygon_domains ? regular_polygon_domain(3) : right_triangle_domain(),
                             std::vector<PatchSide>{edge(f[0], f[1]), edge(f[1], f[2]), edge(f[2], f[0])}, p);
    return patches;
}

// Directed edges of the mesh, keyed by the positions of their ends (vertices are per patch, positions shared),
// that are not matched by exactly one edge the other way: 0 for a closed mesh.
inline int open_edges(const TriangleMeshData& mesh) {
    std::map<std::pair<std::array<float, 3>, std::array<float, 3>>, int> directed;
    auto key = [&](std::uint32_t i) {
        const Vec3f& p = mesh.positions[i];
        return std::array<float, 3>{p.x, p.y, p.z};
    };
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++directed[{key(t[std::size_t(k)]), key(t[std::size_t((k + 1) % 3)])}];
    int open = 0;
    for (const auto& [edge, count] : directed) {
        const auto back = directed.find({edge.second, edge.first});
        if (count != 1 || back == directed.end() || back->second != 1) ++open;
    }
    return open;
}

}  // namespace isotrace::abm_test
