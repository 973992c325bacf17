// The rectangle: hits, edges, grazing rays, uv and its derivatives, placements that keep it a rectangle or shear it
// into a parallelogram (exact either way; solid-angle sampling only for the rectangle), uniform area sampling
// (chi-square over uv), solid-angle samples on the surface with the density pdf() reports, and the scene format.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geometry/csg/csg_test_support.h"
#include "geometry/plane/flat_shape_test_support.h"
#include "geometry/rectangle/rectangle_shape.h"
#include "renderer/sampling/independent_sampler.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

using csg_test::expect_near;
using csg_test::make_ray;
using csg_test::scene_of;

std::array<float, 2> u_sample(std::uint32_t i) {
    static const IndependentSampler sampler(11);
    return {sampler.sample({i, 0, 0}, 0), sampler.sample({i, 0, 0}, 1)};
}

TEST(RectangleShape, HitsEdgesUvAndDerivatives) {
    // 2 m along x, 1 m along −z, at y = 1, facing +y.
    const auto scene = scene_of(std::make_unique<RectangleShape>(Vec3d{0, 1, 0}, Vec3d{2, 0, 0}, Vec3d{0, 0, -1}));
    const auto hit = scene->intersect(make_ray({0.5, 3, -0.25}, {0, -1, 0}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2);
    expect_near(hit->geometric_normal, {0, 1, 0}, 0, "normal");
    EXPECT_NEAR(hit->uv[0], 0.75, 1e-7);
    EXPECT_NEAR(hit->uv[1], 0.75, 1e-7);
    expect_near(hit->dpdu, {2, 0, 0}, 0, "dpdu");
    expect_near(hit->dpdv, {0, 0, -1}, 0, "dpdv");
    EXPECT_TRUE(scene->intersect(make_ray({1, 3, 0.5}, {0, -1, 0}), RayKind::Camera));  // a corner
    EXPECT_FALSE(scene->intersect(make_ray({1.0001, 3, 0}, {0, -1, 0}), RayKind::Camera));
    EXPECT_FALSE(scene->intersect(make_ray({0, 3, 0.5001}, {0, -1, 0}), RayKind::Camera));
    EXPECT_FALSE(scene->intersect(make_ray({-3, 1, 0}, {1, 0, 0}), RayKind::Camera));  // in its plane
    EXPECT_TRUE(scene->occluded(make_ray({0, -1, 0}, {0, 1, 0})));
    const auto below = scene->intersect(make_ray({0, -1, 0}, {0, 1, 0}), RayKind::Camera);
    ASSERT_TRUE(below);
    expect_near(below->geometric_normal, {0, 1, 0}, 0, "the front from behind");
}

TEST(RectangleShape, PlacementsBakeToRectanglesOrParallelograms) {
    const auto shape = [] { return std::make_unique<RectangleShape>(Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{0, 0, -1}); };
    // Scaled along its edges and turned: still a rectangle, sampled by solid angle.
    const auto scaled = scene_of(shape(), Transform::rotate({1, 2, 3}, 50) * Transform::scale({3, 7, 0.5}));
    EXPECT_FALSE(scaled->objects()[0].instanced);
    EXPECT_TRUE(scaled->objects()[0].shape->supports_solid_angle_sampling());
    EXPECT_NEAR(scaled->objects()[0].shape->surface_area(), 1.5, 1e-5);
    // Turned 45° about y before a non-uniform scale: a parallelogram, exact, sampled by area.
    const Transform shear = Transform::scale({2, 1, 1}) * Transform::rotate({0, 1, 0}, 45);
    const auto sheared = scene_of(shape(), shear);
    EXPECT_FALSE(sheared->objects()[0].shape->supports_solid_angle_sampling());
    EXPECT_TRUE(sheared->objects()[0].shape->supports_surface_sampling());
    for (const auto& [s, t, inside] : {std::tuple{0.49, 0.49, true}, {0.51, 0.0, false}, {-0.49, 0.3, true}, {0.2, -0.52, false}}) {
        const Vec3d p = shear.point(Vec3d{s, 0, -t});
        EXPECT_EQ(bool(sheared->intersect(make_ray(p + Vec3d{0, 2, 0}, {0, -1, 0}), RayKind::Camera)), inside) << s << " " << t;
    }
}

TEST(RectangleShape, AreaSamplingIsUniformOverUv) {
    const RectangleShape rectangle({1, 2, 3}, {0, 2, 0}, {0, 0, 0.5});
    EXPECT_NEAR(rectangle.surface_area(), 1, 1e-6);
    constexpr std::uint32_t samples = 50000;
    std::vector<test_support::Point2> points;
    for (std::uint32_t i = 0; i < samples; ++i) {
        const SurfaceSample s = rectangle.sample_surface(u_sample(i));
        ASSERT_NEAR(s.pdf_area, 1, 1e-6);
        expect_near(s.normal, {1, 0, 0}, 0, "normal");
        const auto st = rectangle.frame().coordinates(Vec3d(s.position));
        points.push_back({st[0] + 0.5, st[1] + 0.5});
    }
    const test_support::Grid2D grid{0, 1, 0, 1, 8, 8};
    const auto result = test_support::chi_square_test_2d(grid, points.size(), [&](std::size_t i) { return points[i]; },
                                                         [](double, double) { return 1.0; });
    EXPECT_GT(result.p_value, 0.01) << result.statistic;
}

TEST(RectangleShape, SolidAngleSamplesLieOnItWithTheReportedDensity) {
    const RectangleShape rectangle({0, 2, 0}, {1.5, 0, 0}, {0, 0, -1});
    for (const Vec3f& reference : {Vec3f(0, 0, 0), Vec3f(2, 3, 1), Vec3f(0.2f, 2.01f, 0.1f)}) {
        const float pdf = rectangle.solid_angle_pdf(reference);
        ASSERT_GT(pdf, 0);
        for (std::uint32_t i = 0; i < 200; ++i) {
            const SolidAngleSample s = rectangle.sample_solid_angle(reference, u_sample(i));
            EXPECT_EQ(s.pdf_solid_angle, pdf);
            const auto st = rectangle.frame().coordinates(Vec3d(s.position));
            EXPECT_LE(std::abs(st[0]), 0.5 + 1e-6);
            EXPECT_LE(std::abs(st[1]), 0.5 + 1e-6);
            EXPECT_NEAR(s.position.y, 2, 1e-6);
        }
    }
    // Seen edge-on, or from so far that it subtends almost nothing: not by solid angle (the light samples by area).
    EXPECT_EQ(rectangle.solid_angle_pdf({5, 2, 0}), 0);
    EXPECT_EQ(rectangle.sample_solid_angle({5, 2, 0}, {0.5f, 0.5f}).pdf_solid_angle, 0);
    EXPECT_EQ(rectangle.solid_angle_pdf({0, 500, 0}), 0);
}

TEST(RectangleShapeScene, LoadsSizeOrEdgesAndRejectsBadOnes) {
    mesh_test::ScratchDirectory dir;
    const auto sized = load_scene(dir.write("sized.json", flat_test::scene_with(R"({"type": "rectangle", "center": [0, 1, 0], "size": [2, 0.5]})")));
    EXPECT_TRUE(sized->scene->intersect(make_ray({0.9, 3, 0.2}, {0, -1, 0}), RayKind::Camera));
    EXPECT_FALSE(sized->scene->intersect(make_ray({0.9, 3, 0.3}, {0, -1, 0}), RayKind::Camera));
    const auto edged = load_scene(dir.write("edged.json", flat_test::scene_with(R"({"type": "rectangle", "edge_u": [0, 1, 0], "edge_v": [0, 0, 3]})")));
    const auto hit = edged->scene->intersect(make_ray({2, 0.4, 1.4}, {-1, 0, 0}), RayKind::Camera);
    ASSERT_TRUE(hit);
    expect_near(hit->geometric_normal, {1, 0, 0}, 0, "edge_u × edge_v");
    flat_test::expect_errors(dir, {{R"({"type": "rectangle", "size": [1, 0]})", "objects[0].shape.size"},
                             {R"({"type": "rectangle", "size": [1, 1], "edge_u": [1, 0, 0]})", "not both"},
                             {R"({"type": "rectangle", "edge_u": [1, 0, 0], "edge_v": [1, 0, 1]})", "objects[0].shape.edge_v: the edges must be perpendicular"},
                             {R"({"type": "rectangle", "edge_u": [0, 0, 0]})", "objects[0].shape.edge_u: an edge must be a non-zero vector"}});
}

}  // namespace
}  // namespace isotrace
