#include "renderer/plugin/shadow_ray.h"

#include <gtest/gtest.h>

#include <limits>

namespace isotrace {
namespace {

// A hit on the floor y = 0 at the origin, facing up, with `position_error`.
SurfaceHit floor_hit(float position_error) {
    SurfaceHit hit;
    hit.geometric_normal = hit.shading_normal = {0, 1, 0};
    hit.position_error = position_error;
    return hit;
}

TEST(ShadowRay, AimsAtTheLightPointFromThePushedOrigin) {
    const SurfaceHit hit = floor_hit(1e-3f);
    const Vec3f point{0.9f, 0.01f, -0.2f};
    const Ray ray = shadow_ray(hit, normalize(point), length(point), LightPoint::OnASurface);
    EXPECT_EQ(ray.origin, hit.spawn_origin(point));
    EXPECT_NEAR(length(ray.direction), 1.0f, 1e-6f);
    const Vec3f to_point = point - ray.origin;
    EXPECT_NEAR(dot(ray.direction, normalize(to_point)), 1.0f, 1e-6f);
    EXPECT_NEAR(ray.t_far, length(to_point) * (1 - kShadowRayMargin), 1e-6f);
}

// The light's plane y = 0.01 seen almost edge-on: the ray must end below it. Keeping the direction from the
// unpushed position and its distance, it would end 1 mm (the push) minus 0.1 mm (the margin) too high.
TEST(ShadowRay, EndsShortOfTheLightsPlaneAtGrazingAngles) {
    const SurfaceHit hit = floor_hit(1e-3f);
    const Vec3f point{0.9f, 0.01f, 0};
    const Ray ray = shadow_ray(hit, normalize(point), length(point), LightPoint::OnASurface);
    EXPECT_LT(ray.at(ray.t_far).y, point.y);
    EXPECT_GT(ray.at(ray.t_far).y, hit.position_error);
}

// A point light has no surface: the ray keeps the direction from the pushed origin and ends, short by the margin,
// where it passes closest to the point.
TEST(ShadowRay, BarePointsKeepTheDirectionAndEndBesideThePoint) {
    const SurfaceHit hit = floor_hit(1e-3f);
    const Vec3f point{0.9f, 0.01f, -0.2f};
    const Vec3f direction = normalize(point);
    const Ray ray = shadow_ray(hit, direction, length(point), LightPoint::Bare);
    EXPECT_EQ(ray.origin, hit.spawn_origin(direction));
    EXPECT_EQ(ray.direction, direction);
    const float closest = dot(point - ray.origin, direction);
    EXPECT_NEAR(ray.t_far, closest * (1 - kShadowRayMargin), 1e-6f);
    EXPECT_LT(length(ray.at(closest) - point), 2e-3f);  // across the line by at most the push
}

TEST(ShadowRay, LightsAtInfinityKeepTheDirectionAndTestAllTheWay) {
    const SurfaceHit hit = floor_hit(1e-3f);
    const Vec3f direction = normalize(Vec3f{1, 0.01f, 0});
    const Ray ray = shadow_ray(hit, direction, std::numeric_limits<float>::infinity(), LightPoint::OnASurface);
    EXPECT_EQ(ray.origin, hit.spawn_origin(direction));
    EXPECT_EQ(ray.direction, direction);
    EXPECT_EQ(ray.t_far, std::numeric_limits<float>::infinity());
}

}  // namespace
}  // namespace isotrace
