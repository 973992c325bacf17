// The disk and the annulus: hits inside, misses outside the rim and in the hole, points on the rims, uv and its
// derivatives, an ellipse baked from a non-uniform scale, uniform area sampling (chi-square over ρ² and φ), and the
// scene format.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "geometry/csg/csg_test_support.h"
#include "geometry/disk/disk_shape.h"
#include "geometry/plane/flat_shape_test_support.h"
#include "renderer/sampling/independent_sampler.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

using csg_test::expect_near;
using csg_test::make_ray;
using csg_test::scene_of;

constexpr double kPi = std::numbers::pi;

TEST(DiskShape, HitsInsideMissesOutsideAndInTheHole) {
    const auto scene = scene_of(std::make_unique<DiskShape>(Vec3d{0, 1, 0}, Vec3d{0, 1, 0}, 2, 0.25));
    const auto hit = scene->intersect(make_ray({1, 3, 0.5}, {0, -1, 0}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2);
    expect_near(hit->geometric_normal, {0, 1, 0}, 0, "normal");
    EXPECT_TRUE(scene->intersect(make_ray({2, 3, 0}, {0, -1, 0}), RayKind::Camera));      // on the rim
    EXPECT_TRUE(scene->intersect(make_ray({0, 3, -0.5}, {0, -1, 0}), RayKind::Camera));   // on the inner rim
    EXPECT_FALSE(scene->intersect(make_ray({2.0001, 3, 0}, {0, -1, 0}), RayKind::Camera));  // outside
    EXPECT_FALSE(scene->intersect(make_ray({0.3, 3, 0.3}, {0, -1, 0}), RayKind::Camera));   // in the hole
    EXPECT_FALSE(scene->intersect(make_ray({-5, 1, 0}, {1, 0, 0}), RayKind::Camera));       // in its plane
    EXPECT_TRUE(scene->occluded(make_ray({1, -1, 0}, {0, 1, 0})));
    EXPECT_FALSE(scene->occluded(make_ray({0, -1, 0}, {0, 1, 0})));
}

TEST(DiskShape, UvIsAngleAndRadiusWithTheirDerivatives) {
    const auto scene = scene_of(std::make_unique<DiskShape>(Vec3d{0, 0, 0}, Vec3d{0, 1, 0}, 2, 0));
    // The tangent axes of +y are x and −z: φ = 90° lies along −z.
    const auto hit = scene->intersect(make_ray({0, 1, -1}, {0, -1, 0}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->uv[0], 0.25, 1e-6);
    EXPECT_NEAR(hit->uv[1], 0.5, 1e-6);
    expect_near(hit->dpdv, {0, 0, -2}, 1e-6, "dpdv: radial, the radius per unit v");
    expect_near(hit->dpdu, {-2 * kPi, 0, 0}, 1e-5, "dpdu: 2πρ·radius along the circle");
    const auto behind = scene->intersect(make_ray({-1, 1, 0}, {0, -1, 0}), RayKind::Camera);  // φ = 180°
    ASSERT_TRUE(behind);
    EXPECT_NEAR(behind->uv[0], 0.5, 1e-6);
}

TEST(DiskShape, ANonUniformScaleBakesToAnExactEllipse) {
    const Transform to_world = Transform::rotate({0, 0, 1}, 90) * Transform::scale({3, 1, 0.5});
    const auto scene = scene_of(std::make_unique<DiskShape>(Vec3d{0, 0, 0}, Vec3d{0, 1, 0}, 1, 0), to_world);
    EXPECT_FALSE(scene->objects()[0].instanced);
    // The ellipse x²/9 + z²/0.25 ≤ 1 in the xz plane, turned into the yz plane facing −x.
    EXPECT_TRUE(scene->intersect(make_ray({2, 2.99, 0}, {-1, 0, 0}), RayKind::Camera));
    EXPECT_FALSE(scene->intersect(make_ray({2, 3.01, 0}, {-1, 0, 0}), RayKind::Camera));
    EXPECT_TRUE(scene->intersect(make_ray({2, 0, 0.49}, {-1, 0, 0}), RayKind::Camera));
    EXPECT_FALSE(scene->intersect(make_ray({2, 0, 0.51}, {-1, 0, 0}), RayKind::Camera));
    const auto hit = scene->intersect(make_ray({2, 0, 0}, {-1, 0, 0}), RayKind::Camera);
    ASSERT_TRUE(hit);
    expect_near(hit->geometric_normal, {-1, 0, 0}, 1e-7, "turned normal");
    EXPECT_NEAR(scene->objects()[0].shape->surface_area(), kPi * 1.5, 1e-5);
}

TEST(DiskShape, AreaSamplingIsUniform) {
    const DiskShape disk({1, 2, 3}, normalize(Vec3d{1, 1, 0}), 2, 0.4);
    const double area = kPi * 4 * (1 - 0.16);
    EXPECT_NEAR(disk.surface_area(), area, 1e-5);
    const IndependentSampler sampler(3);
    constexpr std::uint32_t samples = 100000;
    std::vector<test_support::Point2> points;
    for (std::uint32_t i = 0; i < samples; ++i) {
        const SurfaceSample s = disk.sample_surface({sampler.sample({i, 0, 0}, 0), sampler.sample({i, 0, 0}, 1)});
        ASSERT_NEAR(s.pdf_area * area, 1, 1e-6);
        expect_near(s.normal, normalize(Vec3d{1, 1, 0}), 1e-7, "normal");
        const auto st = disk.frame().coordinates(Vec3d(s.position));
        ASSERT_TRUE(disk.covers({st[0] * (1 - 1e-6), st[1] * (1 - 1e-6)}) || disk.covers(st)) << i;
        ASSERT_NEAR(disk.frame().height(Vec3d(s.position)), 0, 1e-5);
        points.push_back({st[0] * st[0] + st[1] * st[1], std::atan2(st[1], st[0])});
    }
    // Uniform by area: ρ² uniform in [0.16, 1], φ uniform.
    const test_support::Grid2D grid{0.16, 1, -kPi, kPi, 8, 8};
    const auto result = test_support::chi_square_test_2d(grid, points.size(), [&](std::size_t i) { return points[i]; },
                                                         [](double, double) { return 1 / (0.84 * 2 * kPi); });
    EXPECT_GT(result.p_value, 0.01) << result.statistic;
}

TEST(DiskShapeScene, LoadsAndRejectsBadRadii) {
    mesh_test::ScratchDirectory dir;
    const auto loaded = load_scene(dir.write("disk.json", flat_test::scene_with(R"({"type": "disk", "center": [0, 0, 1], "normal": [0, 0, 1], "radius": 0.5})")));
    const auto hit = loaded->scene->intersect(make_ray({0.4, 0, 5}, {0, 0, -1}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4);
    EXPECT_FALSE(loaded->scene->intersect(make_ray({0.6, 0, 5}, {0, 0, -1}), RayKind::Camera));
    flat_test::expect_errors(dir, {{R"({"type": "disk", "radius": 0})", "objects[0].shape.radius"},
                             {R"({"type": "disk", "radius": 1, "inner_radius": 1})", "objects[0].shape.inner_radius"},
                             {R"({"type": "disk", "normal": [0, 0, 0]})", "objects[0].shape.normal"},
                             {R"({"type": "disk", "center": [1e18, 0, 0], "radius": 1000})", "lies beyond 1e18"}});
}

}  // namespace
}  // namespace isotrace
