// Surface sampling of sphere sets (area lights), after a real bake by RenderScene with a similarity: spheres
// are chosen in proportion to their area (chi-square), points are uniform on a sphere (chi-square over
// (cos theta, phi)), pdf_area * area = 1, and the normal is the outward normal a ray hit reports.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "geometry/sphere/sphere_shape.h"
#include "renderer/sampling/independent_sampler.h"
#include "renderer/scene/render_scene.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

struct BakedSpheres {
    std::unique_ptr<RenderScene> scene;
    const SphereShape* shape = nullptr;
};

BakedSpheres bake_test_spheres() {
    BakedSpheres result;
    result.scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.shape = std::make_unique<SphereShape>(std::vector<Sphere>{{{0, 0, 0}, 1}, {{5, 0, 0}, 2}, {{0, 6, 0}, 0.5}});
    object.to_world = Transform::translate({1, 2, 3}) * Transform::rotate({0, 1, 1}, 30) * Transform::scale({2, 2, 2});
    result.scene->add_object(std::move(object));
    result.scene->commit();
    result.shape = dynamic_cast<const SphereShape*>(result.scene->objects()[0].shape.get());
    return result;
}

std::array<float, 2> u_sample(uint32_t i) {
    static const IndependentSampler sampler(57);
    return {sampler.sample({i, 0, 0}, 0), sampler.sample({i, 0, 0}, 1)};
}

// The sphere a point lies on (relative tolerance), or -1.
int sphere_of(const std::vector<Sphere>& spheres, const Vec3d& p) {
    for (std::size_t k = 0; k < spheres.size(); ++k)
        if (std::abs(length(p - spheres[k].centre) - spheres[k].radius) < 1e-5 * spheres[k].radius) return int(k);
    return -1;
}

TEST(SphereSampling, AreaPdfAndOutwardNormals) {
    const BakedSpheres baked = bake_test_spheres();
    ASSERT_NE(baked.shape, nullptr);
    ASSERT_FALSE(baked.scene->objects()[0].instanced);
    ASSERT_TRUE(baked.shape->supports_surface_sampling());
    const double area = 4 * std::numbers::pi * 4 * (1 + 4 + 0.25);  // radii doubled by the bake
    EXPECT_NEAR(baked.shape->surface_area(), area, 1e-5 * area);
    for (uint32_t i = 0; i < 500; ++i) {
        const SurfaceSample s = baked.shape->sample_surface(u_sample(i));
        EXPECT_NEAR(s.pdf_area * baked.shape->surface_area(), 1.0, 1e-6);
        const int k = sphere_of(baked.shape->spheres(), Vec3d(s.position));
        ASSERT_GE(k, 0) << "sample " << i << " is on no sphere";
        const Sphere& sphere = baked.shape->spheres()[std::size_t(k)];
        const Vec3d outward = (Vec3d(s.position) - sphere.centre) / sphere.radius;
        EXPECT_NEAR(dot(Vec3d(s.normal), outward), 1.0, 1e-5);
        // The hit normal of a ray arriving from outside along -normal.
        Ray ray;
        ray.origin = s.position + s.normal * 0.5f;
        ray.direction = -s.normal;
        ray.t_far = 1;
        const auto hit = baked.scene->intersect(ray, RayKind::Camera);
        ASSERT_TRUE(hit);
        EXPECT_NEAR(hit->t, 0.5f, 1e-4f);
        EXPECT_NEAR(dot(hit->geometric_normal, s.normal), 1.0f, 1e-5f);
    }
}

TEST(SphereSampling, SpheresAreChosenInProportionToTheirArea) {
    const BakedSpheres baked = bake_test_spheres();
    constexpr uint32_t samples = 100000;
    const auto& spheres = baked.shape->spheres();
    std::vector<double> observed(spheres.size(), 0), expected;
    for (const Sphere& s : spheres)
        expected.push_back(samples * 4 * std::numbers::pi * s.radius * s.radius / baked.shape->surface_area());
    for (uint32_t i = 0; i < samples; ++i) {
        const int k = sphere_of(spheres, Vec3d(baked.shape->sample_surface(u_sample(i)).position));
        ASSERT_GE(k, 0);
        observed[std::size_t(k)] += 1;
    }
    EXPECT_GT(test_support::chi_square_test(observed, expected).p_value, 0.01);
}

TEST(SphereSampling, PointsAreUniformOnEachSphere) {
    const BakedSpheres baked = bake_test_spheres();
    constexpr uint32_t samples = 200000;
    const auto& spheres = baked.shape->spheres();
    for (int k : {1, 2}) {  // the large sphere in the middle of the table, the small one at its end
        std::vector<test_support::Point2> points;  // (cos theta, phi) of the outward direction, z up
        for (uint32_t i = 0; i < samples; ++i) {
            const Vec3d p(baked.shape->sample_surface(u_sample(i)).position);
            if (sphere_of(spheres, p) != k) continue;
            const Vec3d d = (p - spheres[std::size_t(k)].centre) / spheres[std::size_t(k)].radius;
            points.push_back({d.z, std::atan2(d.y, d.x)});
        }
        ASSERT_GT(points.size(), 8000u);  // the small sphere gets 1/21 of the samples
        const test_support::Grid2D grid{-1, 1, -std::numbers::pi, std::numbers::pi, 8, 8};
        const auto result = test_support::chi_square_test_2d(
            grid, points.size(), [&](std::size_t i) { return points[i]; },
            [](double, double) { return 1 / (4 * std::numbers::pi); });
        EXPECT_GT(result.p_value, 0.01) << "sphere " << k << ": statistic " << result.statistic;
    }
}

}  // namespace
}  // namespace isotrace
