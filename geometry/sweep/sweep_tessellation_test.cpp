// Tube tessellation's uvs: (t, θ/2π) at every grid vertex, and a seam after unwrap_tube_seams, where the triangles
// that close the tube around take copies of the v = 0 vertices at v = 1 without moving anything.
#include "geometry/sweep/sweep_tessellation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "geometry/mesh/mesh_closedness.h"
#include "geometry/mesh/mesh_quality.h"
#include "geometry/mesh/vertex_normals.h"
#include "geometry/sweep/sweep_surface.h"
#include "geometry/sweep/sweep_test_support.h"

namespace isotrace {
namespace {

float v_span(const TriangleMeshData& mesh, const std::array<std::uint32_t, 3>& triangle) {
    float low = 1e9f, high = -1e9f;
    for (const std::uint32_t corner : triangle) {
        low = std::min(low, mesh.uvs[corner][1]);
        high = std::max(high, mesh.uvs[corner][1]);
    }
    return high - low;
}

TEST(SweepTessellation, EachGridVertexsUvIsItsCurveParameterAndAngle) {
    const SweepSurface sweep(sweep_test::ring(2, 120, 5, {0.3, 0.5, 0.4, 0.6}));
    const SweepTessellation steps{12, 8, true};
    const TriangleMeshData mesh = tessellate(sweep, steps);
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    const std::size_t grid = std::size_t(steps.theta_steps) * std::size_t(steps.t_steps + 1);
    for (std::size_t i = 0; i < grid; ++i) {
        const Vec3d expected = sweep.point(2 * std::numbers::pi * mesh.uvs[i][1], mesh.uvs[i][0]);
        EXPECT_NEAR(length(Vec3d(mesh.positions[i]) - expected), 0, 1e-5) << i;
    }
    EXPECT_FLOAT_EQ(mesh.uvs[grid][0], 0);  // the caps' centres
    EXPECT_FLOAT_EQ(mesh.uvs[grid + 1][0], 1);
}

TEST(SweepTessellation, UnwrappedSeamsGiveEveryTriangleAShortSpanOfVWithoutMovingAnything) {
    TriangleMeshData mesh = tessellate(SweepSurface(sweep_test::cylinder(0.5, 2, 4)), {16, 6, true});
    compute_vertex_normals(mesh);
    const TriangleMeshData before = mesh;
    int wrapping = 0;
    for (const auto& triangle : mesh.triangles) wrapping += v_span(mesh, triangle) > 0.5f;
    EXPECT_EQ(wrapping, 2 * 6 + 2);  // two per row of the grid and one per cap
    unwrap_tube_seams(mesh);
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    EXPECT_EQ(mesh.positions.size(), before.positions.size() + 7);  // the seam's vertices, once each
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        EXPECT_LE(v_span(mesh, mesh.triangles[t]), 0.5f) << t;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t now = mesh.triangles[t][std::size_t(k)], was = before.triangles[t][std::size_t(k)];
            EXPECT_EQ(mesh.positions[now], before.positions[was]) << t;
            EXPECT_EQ(mesh.normals[now], before.normals[was]) << t;
            EXPECT_EQ(mesh.uvs[now][0], before.uvs[was][0]) << t;
        }
    }
    EXPECT_EQ(closed_mesh_problem(mesh), "");  // still closed: vertices count by position
}

// The torso of scenes/sweep_torso.json (Fig. 2): turning its third key section by 30° keeps every face of the tube
// facing out, stretches no edge beyond 2.5× and makes the tube cross itself nowhere.
TEST(SweepTessellation, TorsoFigureBendsWithoutFolding) {
    const std::vector<std::vector<double>> radii = {
        {0.34, 0.3099, 0.2612, 0.23, 0.22, 0.23, 0.2612, 0.3099, 0.34, 0.3099, 0.2612, 0.23, 0.22, 0.23, 0.2612, 0.3099},
        {0.27, 0.2442, 0.2034, 0.1781, 0.17, 0.1781, 0.2034, 0.2442, 0.27, 0.2442, 0.2034, 0.1781, 0.17, 0.1781, 0.2034, 0.2442},
        {0.33, 0.2994, 0.2506, 0.2198, 0.21, 0.2198, 0.2506, 0.2994, 0.33, 0.2994, 0.2506, 0.2198, 0.21, 0.2198, 0.2506, 0.2994},
        {0.42, 0.343, 0.2554, 0.2124, 0.2, 0.2124, 0.2554, 0.343, 0.42, 0.343, 0.2554, 0.2124, 0.2, 0.2124, 0.2554, 0.343},
        {0.11, 0.1083, 0.1046, 0.1013, 0.1, 0.1013, 0.1046, 0.1083, 0.11, 0.1083, 0.1046, 0.1013, 0.1, 0.1013, 0.1046, 0.1083}};
    const double rise[] = {0, 0.32, 0.3, 0.28, 0.2};
    std::vector<RelativeKeySection> chain;
    for (std::size_t k = 0; k < 5; ++k)
        chain.push_back({{0, k == 0 ? 0.9 : 0.0, rise[k]}, k == 0 ? Quaternion::from_axis_angle({1, 0, 0}, -90) : Quaternion::identity(), radii[k]});
    const SweepSurface modelled(to_absolute(chain));
    edit_key_section(chain, 2, {{}, Quaternion::from_axis_angle({0, 1, 0}, 30), 1, 0});
    const SweepSurface turned(to_absolute(chain), modelled.key_parameters());
    const MeshQuality q = measure_mesh_quality(tessellate(modelled), tessellate(turned));
    EXPECT_EQ(q.flipped_faces, 0u) << describe(q);
    EXPECT_LE(q.max_edge_stretch, 2.5);
    EXPECT_EQ(q.crossing_edges, 0u);
}

}  // namespace
}  // namespace isotrace
