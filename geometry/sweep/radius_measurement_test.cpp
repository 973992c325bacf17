// Radii measured on a mesh: the nearest crossing of rays from the key section's centre, the exact distances for a
// box, and rays whose nearest crossing lies on an edge or a corner (decided by rounding) measured by turned rays.
#include "geometry/sweep/radius_measurement.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace isotrace {
namespace {

// The box [-2, 2]³, triangles counter-clockwise seen from outside.
TriangleMeshData box_of_half_size_two() {
    TriangleMeshData mesh;
    for (std::uint32_t i = 0; i < 8; ++i)
        mesh.positions.push_back(Vec3f(i & 1 ? 2.0f : -2.0f, i & 2 ? 2.0f : -2.0f, i & 4 ? 2.0f : -2.0f));
    mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                      {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return mesh;
}

TEST(RadiusProbe, BoxRadiiAreTheDistancesToItsFaces) {
    const RadiusProbe probe(box_of_half_size_two());
    const std::vector<double> radii = probe.measure({0, 0, 0}, Quaternion::identity(), 8);
    ASSERT_EQ(radii.size(), 8u);
    for (std::size_t j = 0; j < radii.size(); ++j)
        EXPECT_NEAR(radii[j], j % 2 ? 2 * std::sqrt(2.0) : 2.0, 1e-12) << j;  // faces at 0°, 90°…; edges at 45°…
}

// A triangle above the sampling plane touches the ray at 0° with one corner only: whether that ray crosses it is
// rounding's call, and the rays turned a little either way miss it. The radius there is the box's.
TEST(RadiusProbe, ACrossingOnlyAtACornerIsMeasuredByTurnedRays) {
    TriangleMeshData mesh = box_of_half_size_two();
    const auto first = std::uint32_t(mesh.positions.size());
    mesh.positions.push_back(Vec3f(1, 0, 0));
    mesh.positions.push_back(Vec3f(1.5f, 0.5f, 1));
    mesh.positions.push_back(Vec3f(1.5f, -0.5f, 1));
    mesh.triangles.push_back({first, first + 1, first + 2});
    const RadiusProbe probe(mesh);
    const std::vector<double> radii = probe.measure({0, 0, 0}, Quaternion::identity(), 4);
    ASSERT_EQ(radii.size(), 4u);
    EXPECT_NEAR(radii[0], 2.0, 1e-9);
    for (std::size_t j = 1; j < radii.size(); ++j) EXPECT_NEAR(radii[j], 2.0, 1e-12) << j;
}

// A crossing on an edge that the turned rays also cross (the box's own edge at 45°) keeps its distance.
TEST(RadiusProbe, ACrossingOnAnEdgeThatTurnedRaysAlsoCrossKeepsItsDistance) {
    const RadiusProbe probe(box_of_half_size_two());
    const std::vector<double> radii = probe.measure({0, 0, 0}, Quaternion::identity(), 4);
    for (const double r : radii) EXPECT_NEAR(r, 2.0, 1e-9);
    const std::vector<double> diagonal = probe.measure({0, 0, 0}, Quaternion::from_axis_angle({0, 0, 1}, 45), 4);
    for (const double r : diagonal) EXPECT_NEAR(r, 2 * std::sqrt(2.0), 1e-9);
}

}  // namespace
}  // namespace isotrace
