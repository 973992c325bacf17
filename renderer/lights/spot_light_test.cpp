// Spot light: full intensity / d^2 inside the inner cone, nothing outside the outer cone, a smooth falloff
// between, and scene-format errors. With the point and directional lights: delta lights say so, and sample the
// same for every random pair (the path tracer then leaves the light's dimensions uncomputed).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/plugin/light.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

std::unique_ptr<Light> light_from(const std::string& json) {
    const testing::ParsedScene parsed(json);
    return light_registry().create(parsed.root());
}

TEST(SpotLight, IntensityFallsWithDistanceSquaredOnTheAxis) {
    const auto light =
        light_from(R"({"type": "spot", "position": [0, 4, 0], "direction": [0, -1, 0], "intensity": 8})");
    const LightSample s = light->sample({0, 0, 0}, {0.5f, 0.5f});
    EXPECT_TRUE(s.is_delta);
    EXPECT_FLOAT_EQ(s.radiance.r, 8.0f / 16.0f);
    EXPECT_FLOAT_EQ(s.distance, 4.0f);
    EXPECT_NEAR(s.direction.y, 1.0f, 1e-7f);
}

TEST(SpotLight, ConeAndFalloff) {
    const auto light = light_from(
        R"({"type": "spot", "position": [0, 1, 0], "target": [0, 0, 0], "intensity": 1, "cone_angle": 40, "falloff_start": 20})");
    const auto radiance_at_angle = [&](double degrees) {
        const double a = degrees * std::numbers::pi / 180;
        return light->sample(Vec3f(float(std::sin(a)), float(1 - std::cos(a)), 0), {0, 0}).radiance.r;
    };
    EXPECT_FLOAT_EQ(radiance_at_angle(10), 1.0f);   // inside the inner cone, at distance 1
    EXPECT_FLOAT_EQ(radiance_at_angle(45), 0.0f);   // outside the cone
    const float middle = radiance_at_angle(30);
    EXPECT_GT(middle, 0.0f);
    EXPECT_LT(middle, 1.0f);
    EXPECT_GT(radiance_at_angle(25), middle);       // decreasing through the falloff
    EXPECT_LT(radiance_at_angle(35), middle);
    EXPECT_GT(light->power(), 0.0f);
}

TEST(SpotLight, BadParametersAreReported) {
    EXPECT_THROW(light_from(R"({"type": "spot", "position": [0, 1, 0]})"), InputError);
    EXPECT_THROW(light_from(R"({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "target": [0, 0, 0]})"),
                 InputError);
    EXPECT_THROW(light_from(R"({"type": "spot", "position": [0, 1, 0], "direction": [0, 0, 0]})"), InputError);
    EXPECT_THROW(light_from(R"({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "cone_angle": 20, "falloff_start": 30})"),
                 InputError);
}

TEST(DeltaLights, SampleTheSameForEveryRandomPair) {
    for (const char* json : {R"({"type": "point", "position": [0, 2, 0], "intensity": 3})",
                             R"({"type": "spot", "position": [0, 2, 0], "target": [0, 0, 0], "intensity": 3})",
                             R"({"type": "directional", "direction": [0, -1, 0.2], "irradiance": 2})"}) {
        const auto light = light_from(json);
        light->preprocess(Bounds3f{{-1, -1, -1}, {1, 1, 1}});
        EXPECT_TRUE(light->is_delta()) << json;
        const Vec3f point{0.1f, 0.0f, -0.2f};
        const LightSample first = light->sample(point, {0.0f, 0.0f});
        for (const std::array<float, 2> u : {std::array{0.3f, 0.9f}, std::array{0.99f, 0.01f}}) {
            const LightSample other = light->sample(point, u);
            EXPECT_TRUE(other.radiance == first.radiance && other.direction == first.direction &&
                        other.distance == first.distance && other.pdf == first.pdf)
                << json;
        }
    }
}

TEST(DeltaLights, AnEnvironmentIsNotOne) {
    EXPECT_FALSE(light_from(R"({"type": "environment", "radiance": 1})")->is_delta());
}

}  // namespace
}  // namespace isotrace
