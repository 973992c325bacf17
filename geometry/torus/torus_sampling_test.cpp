// Surface sampling of a torus (area lights), after a real bake by RenderScene with a similarity: points are uniform
// by area (chi-square over the two angles, density ∝ R + r·cos θ), pdf_area · area = 1, and each normal is the
// outward one a ray hit reports.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "geometry/cone/round_shapes_test_support.h"
#include "geometry/torus/torus_shape.h"
#include "renderer/sampling/independent_sampler.h"
#include "renderer/scene/render_scene.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

struct Baked {
    std::unique_ptr<RenderScene> scene;
    const TorusShape* shape = nullptr;
};

Baked bake() {
    Torus torus;
    static_cast<AxialFrame&>(torus) = AxialFrame::around({0, 0, 0}, {0, 1, 0});
    torus.major_radius = 1;
    torus.minor_radius = 0.6;
    Baked result;
    result.scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.shape = std::make_unique<TorusShape>(torus);
    object.to_world = Transform::translate({1, 2, 3}) * Transform::rotate({0, 1, 1}, 30) * Transform::scale({2, 2, 2});
    result.scene->add_object(std::move(object));
    result.scene->commit();
    result.shape = dynamic_cast<const TorusShape*>(result.scene->objects()[0].shape.get());
    return result;
}

std::array<float, 2> u_sample(uint32_t i) {
    static const IndependentSampler sampler(33);
    return {sampler.sample({i, 0, 0}, 0), sampler.sample({i, 0, 0}, 1)};
}

TEST(TorusSampling, AreaPdfAndOutwardNormals) {
    const Baked baked = bake();
    ASSERT_FALSE(baked.scene->objects()[0].instanced);
    const double area = 4 * std::numbers::pi * std::numbers::pi * 2 * 1.2;  // radii doubled by the bake
    EXPECT_NEAR(baked.shape->surface_area(), area, 1e-5 * area);
    round_test::expect_samples_hit_back(*baked.scene, *baked.shape, u_sample);
    for (uint32_t i = 0; i < 200; ++i)
        EXPECT_NEAR(torus_distance(baked.shape->torus(), Vec3d(baked.shape->sample_surface(u_sample(i)).position)), 0, 1e-5);
}

TEST(TorusSampling, PointsAreUniformByArea) {
    const Baked baked = bake();
    const Torus& torus = baked.shape->torus();
    constexpr uint32_t samples = 200000;
    std::vector<test_support::Point2> points;  // (θ around the tube, φ around the axis)
    for (uint32_t i = 0; i < samples; ++i) {
        const Vec3d q = torus.local_point(Vec3d(baked.shape->sample_surface(u_sample(i)).position));
        const double rho = std::hypot(q.x, q.y);
        points.push_back({std::atan2(q.z, rho - torus.major_radius), std::atan2(q.y, q.x)});
    }
    const double R = torus.major_radius, r = torus.minor_radius;
    const test_support::Grid2D grid{-std::numbers::pi, std::numbers::pi, -std::numbers::pi, std::numbers::pi, 12, 8};
    const auto result = test_support::chi_square_test_2d(
        grid, points.size(), [&](std::size_t i) { return points[i]; },
        [&](double theta, double) { return (R + r * std::cos(theta)) / (4 * std::numbers::pi * std::numbers::pi * R); });
    EXPECT_GT(result.p_value, 0.01) << "statistic " << result.statistic;
}

}  // namespace
}  // namespace isotrace
