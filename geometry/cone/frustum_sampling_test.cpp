// Surface sampling of frustums (area lights), after a real bake by RenderScene with a similarity: the parts are
// chosen in proportion to their areas, points are uniform on the side (density ∝ R(v) over (v, φ)) and on the caps,
// pdf_area · area = 1, and each normal is the outward one a ray hit reports.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "geometry/cone/frustum_shape.h"
#include "geometry/cone/round_shapes_test_support.h"
#include "renderer/sampling/independent_sampler.h"
#include "renderer/scene/render_scene.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

struct Baked {
    std::unique_ptr<RenderScene> scene;
    const FrustumShape* shape = nullptr;
};

Baked bake(bool caps) {
    Frustum f;
    static_cast<AxialFrame&>(f) = AxialFrame::around({0, 0, 0}, {0, 1, 0});
    f.height = 2;
    f.base_radius = 1;
    f.top_radius = 0.25;
    f.caps = caps;
    Baked result;
    result.scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.shape = std::make_unique<FrustumShape>("cone", f);
    object.to_world = Transform::translate({1, 2, 3}) * Transform::rotate({0, 1, 1}, 30) * Transform::scale({2, 2, 2});
    result.scene->add_object(std::move(object));
    result.scene->commit();
    result.shape = dynamic_cast<const FrustumShape*>(result.scene->objects()[0].shape.get());
    return result;
}

std::array<float, 2> u_sample(uint32_t i) {
    static const IndependentSampler sampler(91);
    return {sampler.sample({i, 0, 0}, 0), sampler.sample({i, 0, 0}, 1)};
}

// After the bake by 2: radii 2 and 0.5, height 4, slant √(4² + 1.5²).
const double kSide = std::numbers::pi * 2.5 * std::sqrt(18.25);
constexpr double kBase = std::numbers::pi * 4, kTop = std::numbers::pi * 0.25;

TEST(FrustumSampling, AreaPdfAndOutwardNormals) {
    for (const bool caps : {true, false}) {
        const Baked baked = bake(caps);
        ASSERT_FALSE(baked.scene->objects()[0].instanced);
        ASSERT_TRUE(baked.shape->supports_surface_sampling());
        const double area = caps ? kSide + kBase + kTop : kSide;
        EXPECT_NEAR(baked.shape->surface_area(), area, 1e-5 * area);
        round_test::expect_samples_hit_back(*baked.scene, *baked.shape, u_sample);
    }
}

TEST(FrustumSampling, PartsInProportionToAreaAndUniformOnEach) {
    const Baked baked = bake(true);
    const Frustum& f = baked.shape->frustum();
    constexpr uint32_t samples = 200000;
    std::vector<double> parts(3, 0);
    std::vector<test_support::Point2> side, base;  // (v, φ) on the side; (ρ², φ) on the base, both uniform in these
    for (uint32_t i = 0; i < samples; ++i) {
        const Vec3d q = f.local_point(Vec3d(baked.shape->sample_surface(u_sample(i)).position));
        const double rho = std::hypot(q.x, q.y), phi = std::atan2(q.y, q.x);
        if (std::abs(q.z) < 1e-4) {
            parts[1] += 1;
            base.push_back({rho * rho / (f.base_radius * f.base_radius), phi});
        } else if (std::abs(q.z - f.height) < 1e-4) {
            parts[2] += 1;
        } else {
            parts[0] += 1;
            side.push_back({q.z / f.height, phi});
        }
    }
    const double total = kSide + kBase + kTop;
    const std::vector<double> expected{samples * kSide / total, samples * kBase / total, samples * kTop / total};
    EXPECT_GT(test_support::chi_square_test(parts, expected).p_value, 0.01);
    const test_support::Grid2D grid{0, 1, -std::numbers::pi, std::numbers::pi, 8, 8};
    // On the side the density in (v, φ) is ∝ R(v) = 2 − 1.5 v; normalised over [0, 1] × [−π, π).
    auto result = test_support::chi_square_test_2d(
        grid, side.size(), [&](std::size_t i) { return side[i]; },
        [](double v, double) { return (2 - 1.5 * v) / (1.25 * 2 * std::numbers::pi); });
    EXPECT_GT(result.p_value, 0.01) << "side: statistic " << result.statistic;
    result = test_support::chi_square_test_2d(
        grid, base.size(), [&](std::size_t i) { return base[i]; },
        [](double, double) { return 1 / (2 * std::numbers::pi); });
    EXPECT_GT(result.p_value, 0.01) << "base: statistic " << result.statistic;
}

}  // namespace
}  // namespace isotrace
