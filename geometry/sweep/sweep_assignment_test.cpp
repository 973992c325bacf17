#include "geometry/sweep/sweep_assignment.h"

#include <gtest/gtest.h>

namespace isotrace {
namespace {

// A strip of triangles along x: vertices 2i at (i, 0, 0) and 2i + 1 at (i, 1, 0), i < columns.
TriangleMeshData strip(int columns) {
    TriangleMeshData mesh;
    for (int i = 0; i < columns; ++i) {
        mesh.positions.push_back({float(i), 0, 0});
        mesh.positions.push_back({float(i), 1, 0});
    }
    for (std::uint32_t i = 0; i + 1 < std::uint32_t(columns); ++i) {
        mesh.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 1});
        mesh.triangles.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
    }
    return mesh;
}

// A binding at depth u = (r + d)/r of a unit radius.
std::optional<VertexBinding> at_depth(double u) { return VertexBinding{0, 0.5, u - 1, 1}; }

TEST(SweepAssignment, AmbiguousVerticesFollowTheirNeighboursNotTheDeepestSweep) {
    // Sweep 0 holds columns 0–3, sweep 1 columns 2–5; columns 2 and 3 lie inside both, deeper in sweep 1 at
    // column 2 (a spout's root in the body's wall), so the depth alone would split them.
    const TriangleMeshData mesh = strip(6);
    SweepBindings bindings(2, std::vector<std::optional<VertexBinding>>(12));
    for (int v = 0; v < 8; ++v) bindings[0][std::size_t(v)] = at_depth(0.5);
    for (int v = 4; v < 12; ++v) bindings[1][std::size_t(v)] = at_depth(v < 6 ? 0.1 : 0.5);
    const std::vector<int> owner = assign_sweeps(mesh, vertex_neighbours(mesh), bindings, {});
    const std::vector<int> expected = {0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1};
    // Columns 2 (distance 1 from sweep 0's own vertices) and 3 (distance 1 from sweep 1's): each the nearer.
    EXPECT_EQ(owner, expected);
}

TEST(SweepAssignment, GroupsOverrideAndSeedTheGrowth) {
    const TriangleMeshData mesh = strip(4);
    SweepBindings bindings(2, std::vector<std::optional<VertexBinding>>(8, at_depth(0.5)));
    std::vector<int> grouped(8, -1);
    grouped[0] = grouped[1] = 1;  // column 0 named for sweep 1; the rest is inside both sweeps
    const std::vector<int> owner = assign_sweeps(mesh, vertex_neighbours(mesh), bindings, grouped);
    EXPECT_EQ(owner, std::vector<int>(8, 1));
}

TEST(SweepAssignment, UnreachedVerticesFollowTheDeepestSweepAndUnboundOnesNone) {
    TriangleMeshData mesh = strip(2);
    mesh.positions.push_back({5, 5, 5});  // a vertex of no triangle
    SweepBindings bindings(2, std::vector<std::optional<VertexBinding>>(5));
    for (int v = 0; v < 4; ++v) {
        bindings[0][std::size_t(v)] = at_depth(0.8);
        bindings[1][std::size_t(v)] = at_depth(0.3);
    }
    const std::vector<int> owner = assign_sweeps(mesh, vertex_neighbours(mesh), bindings, {});
    EXPECT_EQ(owner, (std::vector<int>{1, 1, 1, 1, -1}));
}

TEST(SweepAssignment, BlendsAcrossTheSeamWithinTheWidth) {
    const TriangleMeshData mesh = strip(4);
    SweepBindings bindings(2, std::vector<std::optional<VertexBinding>>(8, at_depth(0.5)));
    const std::vector<int> owner = {0, 0, 0, 0, 1, 1, 1, 1};
    const auto shares = blend_sweeps(mesh, vertex_neighbours(mesh), bindings, owner, {1.5, 1.5});
    // Column 1 is 1 from sweep 1's column 2: weight 1 − 1/1.5 = 1/3 for sweep 1 before normalising.
    ASSERT_EQ(shares[2].size(), 2u);
    EXPECT_NEAR(shares[2][1].weight, (1.0 / 3) / (1 + 1.0 / 3), 1e-12);
    EXPECT_EQ(shares[0].size(), 1u);  // column 0: two away, beyond the width
    const auto none = blend_sweeps(mesh, vertex_neighbours(mesh), bindings, owner, {0, 0});
    for (const auto& share : none) EXPECT_EQ(share.size(), 1u);
}

}  // namespace
}  // namespace isotrace
