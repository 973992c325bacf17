// The preview integrator against closed forms: a Lambertian plane under a directional light gives
// albedo * E * cos(theta) / pi; under an unoccluded uniform ambient it gives albedo * L_a; emission adds;
// misses see the background; an occluder casts a shadow from a point light.
#include "integrators/preview/preview_integrator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "renderer/sampling/independent_sampler.h"
#include "renderer/sampling/sampler.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

using testing::SceneFile;

// A 40 x 40 floor at y = 0 whose front faces +y, plus whatever else the test adds.
std::string scene_json(const std::string& integrator, const std::string& material, const std::string& lights,
                       const std::string& more_objects = "") {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 5, 5], "target": [0, 0, 0]}},
  "integrator": )" +
           integrator + R"(,
  "materials": {"floor": )" +
           material + R"(, "grey": {"type": "diffuse", "reflectance": 0.5}},
  "lights": [)" +
           lights + R"(],
  "objects": [{"name": "floor", "material": "floor", "shape": {"type": "mesh",
    "positions": [[-20, 0, -20], [-20, 0, 20], [20, 0, 20], [20, 0, -20]], "triangles": [[0, 1, 2], [0, 2, 3]]}})" +
           more_objects + "]}";
}

struct Shot {
    Rgb radiance;
    PrimaryHitRecord primary;
};

// Radiance along the ray from `from` to `to`, with sample index `index` of an independent sampler.
Shot shoot(const LoadedScene& scene, const Vec3f& from, const Vec3f& to, std::uint32_t index = 0) {
    static const IndependentSampler sampler(99);
    SampleStream samples(sampler, {1, 2, index});
    Ray ray;
    ray.origin = from;
    ray.direction = normalize(to - from);
    Shot shot;
    shot.radiance = scene.integrator->radiance(ray, *scene.scene, samples, shot.primary);
    return shot;
}

void expect_rgb_near(const Rgb& actual, const Rgb& expected, float relative, const std::string& what = "") {
    EXPECT_NEAR(actual.r, expected.r, relative * std::abs(expected.r) + 1e-7f) << what;
    EXPECT_NEAR(actual.g, expected.g, relative * std::abs(expected.g) + 1e-7f) << what;
    EXPECT_NEAR(actual.b, expected.b, relative * std::abs(expected.b) + 1e-7f) << what;
}

constexpr const char* kNoAmbient = R"({"type": "preview", "ambient": 0, "background": [0.1, 0.2, 0.3]})";
constexpr const char* kFloorMaterial = R"({"type": "diffuse", "reflectance": [0.8, 0.5, 0.25]})";

TEST(PreviewIntegrator, DirectionalLightOnALambertianPlaneIsAlbedoTimesIrradianceTimesCosineOverPi) {
    const Rgb albedo(0.8f, 0.5f, 0.25f), irradiance(2.0f, 3.0f, 1.5f);
    for (double theta_degrees : {0.0, 30.0, 60.0, 85.0}) {
        const double theta = theta_degrees * std::numbers::pi / 180;
        // "direction" is where the light travels: down and sideways, at theta from the normal.
        const std::string dx = std::to_string(-std::sin(theta)), dy = std::to_string(-std::cos(theta));
        const std::string light =
            R"({"type": "directional", "irradiance": [2, 3, 1.5], "direction": [)" + dx + ", " + dy + ", 0]}";
        const SceneFile file(scene_json(kNoAmbient, kFloorMaterial, light));
        const auto scene = load_scene(file.path());
        const float cosine = float(-std::stod(dy) / std::hypot(std::stod(dx), std::stod(dy)));  // as written
        const Rgb expected = albedo * irradiance * (cosine * float(std::numbers::inv_pi));
        for (const Vec3f& target : {Vec3f(0, 0, 0), Vec3f(3.5f, 0, -2), Vec3f(-7, 0, 9)}) {
            const Shot shot = shoot(*scene, {1, 4, 3}, target);
            expect_rgb_near(shot.radiance, expected, 1e-5f, "theta " + std::to_string(theta_degrees));
            ASSERT_TRUE(shot.primary.hit);
            EXPECT_EQ(shot.primary.albedo, albedo);
            EXPECT_EQ(shot.primary.shading_normal, Vec3f(0, 1, 0));
            EXPECT_NEAR(shot.primary.position.x, target.x, 1e-5f);
            EXPECT_NEAR(shot.primary.position.y, 0, 1e-5f);
            EXPECT_NEAR(shot.primary.position.z, target.z, 1e-5f);
            EXPECT_EQ(shot.primary.object_id, 0u);
        }
    }
}

TEST(PreviewIntegrator, LightBelowTheHorizonContributesNothing) {
    const SceneFile file(scene_json(kNoAmbient, kFloorMaterial,
                                    R"({"type": "directional", "irradiance": 5, "direction": [0.2, 1, 0]})"));
    const auto scene = load_scene(file.path());
    EXPECT_EQ(shoot(*scene, {0, 3, 0}, {0.5f, 0, 0.5f}).radiance, Rgb(0));
}

TEST(PreviewIntegrator, PlaneSeenFromBelowIsShadedOnItsLitSide) {
    // Two-sided shading: from below, the normal turns towards the viewer and a light above cannot reach it.
    const SceneFile file(scene_json(kNoAmbient, kFloorMaterial,
                                    R"({"type": "directional", "irradiance": 5, "direction": [0, -1, 0]})"));
    const auto scene = load_scene(file.path());
    const Shot below = shoot(*scene, {0, -3, 0}, {0.5f, 0, 0.5f});
    EXPECT_EQ(below.radiance, Rgb(0));
    EXPECT_EQ(below.primary.shading_normal, Vec3f(0, -1, 0));
}

TEST(PreviewIntegrator, UnoccludedAmbientGivesAlbedoTimesAmbientExactly) {
    for (int ambient_samples : {1, 4, 16}) {
        const std::string integrator = R"({"type": "preview", "ambient": [0.3, 0.6, 0.9], "ambient_samples": )" +
                                       std::to_string(ambient_samples) + "}";
        const SceneFile file(scene_json(integrator, kFloorMaterial, ""));
        const auto scene = load_scene(file.path());
        for (std::uint32_t index = 0; index < 32; ++index) {
            const Shot shot = shoot(*scene, {1, 4, 3}, {float(index % 5) - 2, 0, float(index % 7) - 3}, index);
            // Every ambient-occlusion ray escapes, so the estimate has no noise at all.
            EXPECT_EQ(shot.radiance, Rgb(0.8f, 0.5f, 0.25f) * Rgb(0.3f, 0.6f, 0.9f)) << index;
        }
    }
}

TEST(PreviewIntegrator, EnclosedPointSeesNoAmbientUnlessTheDistanceIsClipped) {
    // A sphere of radius 10 around everything (seen from inside) occludes every ambient ray...
    const std::string enclosure =
        R"(, {"name": "dome", "material": "grey", "shape": {"type": "sphere", "center": [0, 0, 0], "radius": 10}})";
    {
        const SceneFile file(scene_json(R"({"type": "preview", "ambient": 1, "ambient_samples": 8})", kFloorMaterial,
                                        "", enclosure));
        const auto scene = load_scene(file.path());
        for (std::uint32_t index = 0; index < 16; ++index)
            EXPECT_EQ(shoot(*scene, {1, 4, 3}, {0, 0, 0}, index).radiance, Rgb(0)) << index;
    }
    // ... unless the ambient rays are clipped short of it.
    {
        const SceneFile file(scene_json(
            R"({"type": "preview", "ambient": 1, "ambient_samples": 8, "ambient_distance": 5})", kFloorMaterial, "",
            enclosure));
        const auto scene = load_scene(file.path());
        for (std::uint32_t index = 0; index < 16; ++index)
            EXPECT_EQ(shoot(*scene, {1, 4, 3}, {0, 0, 0}, index).radiance, Rgb(0.8f, 0.5f, 0.25f)) << index;
    }
}

TEST(PreviewIntegrator, EmissionIsOneSidedUnlessAskedOtherwise) {
    for (const bool two_sided : {false, true}) {
        const std::string emitter = std::string(R"({"type": "emissive", "radiance": [1, 2, 4], "two_sided": )") +
                                    (two_sided ? "true" : "false") + "}";
        const SceneFile file(scene_json(kNoAmbient, emitter, ""));
        const auto scene = load_scene(file.path());
        EXPECT_EQ(shoot(*scene, {0, 2, 0}, {0.5f, 0, 0}).radiance, Rgb(1, 2, 4)) << two_sided;  // front
        EXPECT_EQ(shoot(*scene, {0, -2, 0}, {0.5f, 0, 0}).radiance, two_sided ? Rgb(1, 2, 4) : Rgb(0))
            << two_sided;  // back
    }
}

TEST(PreviewIntegrator, PureEmittersReflectNothing) {
    {  // A pure emitter reflects nothing, whatever the lights and ambient.
        const SceneFile file(scene_json(R"({"type": "preview", "ambient": 1})",
                                        R"({"type": "emissive", "radiance": [3, 2, 1], "scale": 2})",
                                        R"({"type": "directional", "irradiance": 2, "direction": [0, -1, 0]})"));
        const auto scene = load_scene(file.path());
        const Shot shot = shoot(*scene, {0, 2, 0}, {0.5f, 0, 0});
        EXPECT_EQ(shot.radiance, Rgb(6, 4, 2));
        EXPECT_TRUE(shot.primary.hit);
        EXPECT_EQ(shot.primary.albedo, Rgb(0));
    }
}

TEST(PreviewIntegrator, MissesSeeTheBackground) {
    {
        const SceneFile file(scene_json(kNoAmbient, kFloorMaterial,
                                        R"({"type": "directional", "irradiance": 2, "direction": [0, -1, 0]})"));
        const auto scene = load_scene(file.path());
        const Shot shot = shoot(*scene, {0, 2, 0}, {0, 5, 1});
        EXPECT_EQ(shot.radiance, Rgb(0.1f, 0.2f, 0.3f));
        EXPECT_FALSE(shot.primary.hit);
    }
    {  // Without "background" the sky the ambient term assumes is also what misses see.
        const SceneFile file(scene_json(R"({"type": "preview", "ambient": [0.4, 0.5, 0.6]})", kFloorMaterial, ""));
        const auto scene = load_scene(file.path());
        EXPECT_EQ(shoot(*scene, {0, 2, 0}, {0, 5, 1}).radiance, Rgb(0.4f, 0.5f, 0.6f));
    }
}

TEST(PreviewIntegrator, PointLightBehindAnOccluderCastsAShadow) {
    const std::string light = R"({"type": "point", "position": [0, 4, 0], "intensity": [8, 8, 8]})";
    const std::string blocker =
        R"(, {"name": "blocker", "material": "grey", "shape": {"type": "sphere", "center": [0, 2, 0], "radius": 0.5}})";
    const SceneFile file(scene_json(kNoAmbient, kFloorMaterial, light, blocker));
    const auto scene = load_scene(file.path());
    // Under the sphere: in its shadow.
    const Shot shadowed = shoot(*scene, {3, 3, 3}, {0.1f, 0, -0.1f});
    ASSERT_TRUE(shadowed.primary.hit);
    EXPECT_EQ(shadowed.primary.object_id, 0u);
    EXPECT_EQ(shadowed.radiance, Rgb(0));
    // Away from it: lit, with the inverse-square law and the cosine.
    const Vec3f lit_point(3, 0, 1);
    const Shot lit = shoot(*scene, {3, 3, 4}, lit_point);
    const Vec3f to_light = Vec3f(0, 4, 0) - lit_point;
    const float distance_squared = dot(to_light, to_light);
    const float cosine = to_light.y / std::sqrt(distance_squared);
    const Rgb expected = Rgb(0.8f, 0.5f, 0.25f) * (8.0f / distance_squared * cosine * float(std::numbers::inv_pi));
    expect_rgb_near(lit.radiance, expected, 1e-5f);
    // The blocker itself is lit on top and dark underneath.
    EXPECT_GT(shoot(*scene, {0, 3.5f, 0.5f}, {0, 2.5f, 0}).radiance.r, 0.0f);
    EXPECT_EQ(shoot(*scene, {0.1f, 0.2f, 0.1f}, {0, 1.5f, 0}).radiance, Rgb(0));
}

TEST(PreviewIntegrator, LightsAddUp) {
    const std::string lights =
        R"({"type": "directional", "irradiance": 1, "direction": [0, -1, 0]},
           {"type": "directional", "irradiance": 2, "direction": [-1, -1, 0]})";
    const SceneFile file(scene_json(kNoAmbient, kFloorMaterial, lights));
    const auto scene = load_scene(file.path());
    const float e = 1.0f + 2.0f * float(std::sqrt(0.5));
    expect_rgb_near(shoot(*scene, {0, 2, 1}, {0, 0, 0}).radiance,
                    Rgb(0.8f, 0.5f, 0.25f) * (e * float(std::numbers::inv_pi)), 1e-5f);
}

}  // namespace
}  // namespace isotrace
