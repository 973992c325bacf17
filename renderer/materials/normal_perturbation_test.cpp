#include "renderer/materials/normal_perturbation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

namespace isotrace {
namespace {

// A height field given by a function of the world-space point.
class HeightField final : public ScalarTexture {
public:
    explicit HeightField(std::function<float(const Vec3f&)> height) : height_(std::move(height)) {}
    float evaluate(const TextureContext& at) const override { return height_(at.position); }

private:
    std::function<float(const Vec3f&)> height_;
};

SurfaceHit plane_hit(const Vec3f& position) {
    SurfaceHit hit;
    hit.position = position;
    hit.geometric_normal = hit.shading_normal = {0, 0, 1};
    hit.footprint = 1e-3f;
    return hit;
}

Vec3f bumped_normal(const NormalPerturbation& bump, const Vec3f& position) {
    SurfaceHit hit = plane_hit(position);
    bump.apply(hit);
    return hit.shading_normal;
}

TEST(NormalPerturbation, LinearHeightOnAPlaneGivesTheAnalyticNormal) {
    // h = 0.3 x + 0.2 y, raised by 0.5 per unit: the surface z = 0.15 x + 0.1 y.
    const NormalPerturbation bump(
        std::make_shared<HeightField>([](const Vec3f& p) { return 0.3f * p.x + 0.2f * p.y; }), 0.5f, nullptr, 1);
    const Vec3f expected = normalize(Vec3f(-0.15f, -0.1f, 1));
    for (const Vec3f& p : {Vec3f(0, 0, 0), Vec3f(2, -1, 0), Vec3f(-3, 5, 0)}) {
        const Vec3f n = bumped_normal(bump, p);
        EXPECT_NEAR(n.x, expected.x, 1e-3f);
        EXPECT_NEAR(n.y, expected.y, 1e-3f);
        EXPECT_NEAR(n.z, expected.z, 1e-3f);
    }
}

TEST(NormalPerturbation, SineHeightOnAPlaneGivesTheAnalyticNormal) {
    // z = 0.2 sin(3x): the normal is (−0.6 cos(3x), 0, 1) normalised; forward differences over half the footprint.
    const NormalPerturbation bump(std::make_shared<HeightField>([](const Vec3f& p) { return std::sin(3 * p.x); }),
                                  0.2f, nullptr, 1);
    for (float x : {0.0f, 0.4f, 1.1f, 2.5f}) {
        const Vec3f n = bumped_normal(bump, {x, 0.7f, 0});
        const Vec3f expected = normalize(Vec3f(-0.6f * std::cos(3 * x), 0, 1));
        EXPECT_NEAR(n.x, expected.x, 2e-3f) << x;
        EXPECT_NEAR(n.y, expected.y, 2e-3f) << x;
        EXPECT_NEAR(n.z, expected.z, 2e-3f) << x;
    }
}

TEST(NormalPerturbation, ConstantHeightLeavesTheNormal) {
    const NormalPerturbation bump(std::make_shared<HeightField>([](const Vec3f&) { return 0.7f; }), 1.0f, nullptr, 1);
    const Vec3f n = bumped_normal(bump, {1, 2, 0});
    EXPECT_EQ(n, Vec3f(0, 0, 1));
}

TEST(NormalPerturbation, SteepBumpsNeverTiltPastTheLimit) {
    const NormalPerturbation bump(std::make_shared<HeightField>([](const Vec3f& p) { return 1000 * p.x; }), 1.0f,
                                  nullptr, 1);
    const Vec3f n = bumped_normal(bump, {0.5f, 0, 0});
    const float limit = std::cos(NormalPerturbation::kMaxTiltDegrees * std::numbers::pi_v<float> / 180);
    EXPECT_NEAR(dot(n, Vec3f(0, 0, 1)), limit, 1e-5f);
    EXPECT_NEAR(length(n), 1.0f, 1e-5f);
    EXPECT_LT(n.x, 0);  // tilted away from the rising side
}

TEST(KeepAboveSurface, NormalsBelowTheSurfaceComeUpToTheLimit) {
    const Vec3f geometric(0, 0, 1);
    const float limit = std::cos(NormalPerturbation::kMaxTiltDegrees * std::numbers::pi_v<float> / 180);
    const Vec3f below = keep_above_surface(normalize(Vec3f(1, 0, -0.5f)), geometric);
    EXPECT_NEAR(dot(below, geometric), limit, 1e-6f);
    EXPECT_GT(below.x, 0);
    const Vec3f fine = normalize(Vec3f(0.3f, 0.2f, 1));
    EXPECT_EQ(keep_above_surface(fine, geometric), fine);
}

// A normal map that stores one tangent-space normal everywhere.
class StoredNormal final : public ColourTexture {
public:
    explicit StoredNormal(const Vec3f& n) : stored_((n.x + 1) / 2, (n.y + 1) / 2, (n.z + 1) / 2) {}
    Rgb evaluate(const TextureContext&) const override { return stored_; }

private:
    Rgb stored_;
};

TEST(NormalPerturbation, NormalMapFollowsTheUvFrame) {
    const Vec3f stored = normalize(Vec3f(0.3f, -0.2f, 1));
    const NormalPerturbation map(nullptr, 0, std::make_shared<StoredNormal>(stored), 1);
    SurfaceHit hit = plane_hit({0, 0, 0});
    hit.dpdu = {0, 2, 0};   // u runs along +y
    hit.dpdv = {-1, 0, 0};  // v along −x: a right-handed uv frame (u × v = +z)
    map.apply(hit);
    EXPECT_NEAR(hit.shading_normal.y, stored.x, 2e-3f);
    EXPECT_NEAR(hit.shading_normal.x, -stored.y, 2e-3f);
    EXPECT_NEAR(hit.shading_normal.z, stored.z, 2e-3f);
    // Mirrored uv (v along +x) mirrors the map's y.
    SurfaceHit mirrored = plane_hit({0, 0, 0});
    mirrored.dpdu = {0, 2, 0};
    mirrored.dpdv = {1, 0, 0};
    map.apply(mirrored);
    EXPECT_NEAR(mirrored.shading_normal.x, stored.y, 2e-3f);
}

TEST(NormalPerturbation, NormalMapWithoutUvFrameLeavesTheNormal) {
    const NormalPerturbation map(nullptr, 0, std::make_shared<StoredNormal>(normalize(Vec3f(0.5f, 0, 1))), 1);
    SurfaceHit hit = plane_hit({0, 0, 0});
    map.apply(hit);
    EXPECT_EQ(hit.shading_normal, Vec3f(0, 0, 1));
}

}  // namespace
}  // namespace isotrace
