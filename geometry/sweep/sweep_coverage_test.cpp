#include "geometry/sweep/sweep_coverage.h"

#include <gtest/gtest.h>

namespace isotrace {
namespace {

TEST(SweepCoverage, CountsEdgesFromMovedVerticesToUncoveredOnes) {
    // Vertex 0 is moved; 1 lies beyond the sweep's ends, 2 outside its surface at 1.3 × its radius, 3 inside
    // but unmoved (its weight is 0 at the surface: not a coverage problem), 4 moved a little.
    const VertexNeighbours next = {{1, 2, 3, 4}, {0}, {0}, {0}, {0}};
    const std::vector<std::optional<VertexBinding>> bindings = {VertexBinding{0, 0.5, -0.5, 1}, std::nullopt,
                                                                VertexBinding{0, 0.5, 0.3, 1}, VertexBinding{0, 0.5, 0, 1},
                                                                VertexBinding{0, 0.5, -0.1, 1}};
    const SweepCoverage c = sweep_coverage(next, bindings, {1, 0, 0, 0, 0.2});
    EXPECT_EQ(c.end_plane_edges, 1u);
    EXPECT_EQ(c.outside_edges, 1u);
    EXPECT_DOUBLE_EQ(c.largest_outside_u, 1.3);
    EXPECT_EQ(describe(c, 2), "1 edges leave the sweep through its surface from moved vertices (out to 1.30 × its radius: "
                              "measured_radius_scale 2.86 would enclose them), 1 edges from moved vertices cross its end planes");
    EXPECT_EQ(describe(SweepCoverage{}, 1), "");
}

}  // namespace
}  // namespace isotrace
