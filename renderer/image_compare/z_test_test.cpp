// The per-pixel z-test: worked numbers on synthetic images, then real renders — an unbiased low-budget render
// passes against a high-budget reference with another seed; the same render 2 % too bright fails, and so does a
// render with one material 2 % brighter.
#include "renderer/image_compare/z_test.h"

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

ZTestInput uniform_input(int width, int height, float mean, float variance_of_mean, float reference_spp, float test,
                         float test_spp) {
    ZTestInput input;
    input.reference_mean = RgbImage(width, height, mean);
    input.reference_variance = RgbImage(width, height, variance_of_mean);
    input.reference_samples.assign(std::size_t(width) * std::size_t(height), reference_spp);
    input.test = RgbImage(width, height, test);
    input.test_samples.assign(std::size_t(width) * std::size_t(height), test_spp);
    return input;
}

TEST(ZTest, SidakCorrectedSignificance) {
    // alpha = 1 - 0.99^(1/100) = 1.00498...e-4 for 100 pixels.
    const ZTestResult result = z_test(uniform_input(10, 10, 1, 0.01f, 100, 1, 4));
    EXPECT_NEAR(result.alpha, 1 - std::pow(0.99, 0.01), 1e-15);
    EXPECT_TRUE(result.passed);
    EXPECT_EQ(result.pass_fraction, 1.0);
}

TEST(ZTest, ZStatisticWorkedByHand) {
    // Reference variance of the mean 0.0001 at 100 spp: per-sample variance 0.01. Test at 4 spp:
    // standard error sqrt(0.01 / 4 + 0.01 / 100) = 0.0509902; a difference of 0.25 is z = 4.90290, two-sided
    // p = erfc(4.90290 / sqrt 2) = 9.44e-7 < alpha (1.005e-4 for 100 pixels): every channel fails.
    const ZTestResult far = z_test(uniform_input(10, 10, 1, 1e-4f, 100, 1.25f, 4));
    EXPECT_NEAR(far.min_p_value, std::erfc(0.25 / std::sqrt(0.01 / 4 + 0.01 / 100) / std::sqrt(2.0)), 1e-9);
    EXPECT_EQ(far.failed_channels, 300);
    EXPECT_FALSE(far.passed);
    // A difference of 0.15 is z = 2.94 (p = 0.0033 > alpha): all pass.
    EXPECT_TRUE(z_test(uniform_input(10, 10, 1, 1e-4f, 100, 1.15f, 4)).passed);
}

TEST(ZTest, VarianceFloorKeepsNoiselessPixelsFromFailingOnRounding) {
    // Zero variance (a background pixel): the floor 1e-4 makes the standard error sqrt(1e-4/16 + 1e-4/64),
    // 0.0028; a difference of 1e-6 is z = 0.00036 and passes, 0.05 is z = 17.9 and fails.
    EXPECT_TRUE(z_test(uniform_input(8, 8, 0.5f, 0, 64, 0.500001f, 16)).passed);
    EXPECT_FALSE(z_test(uniform_input(8, 8, 0.5f, 0, 64, 0.55f, 16)).passed);
}

TEST(ZTest, PassesWhenAtMostOneInFourHundredChannelsFails) {
    // 100 pixels = 300 channels; 99.75 % must pass: 0 failures pass, and so would 0.75; one failing channel is
    // 1/300 = 0.33 % > 0.25 % and fails the image.
    ZTestInput input = uniform_input(10, 10, 1, 1e-4f, 100, 1, 4);
    EXPECT_TRUE(z_test(input).passed);
    input.test.values[0] = 5;
    const ZTestResult one = z_test(input);
    EXPECT_EQ(one.failed_channels, 1);
    EXPECT_FALSE(one.passed);
    EXPECT_EQ(one.failed_per_pixel[0], 1.0f);
}

TEST(ZTest, RefusesMissingSampleCounts) {
    ZTestInput input = uniform_input(4, 4, 1, 1e-4f, 100, 1, 4);
    input.test_samples[3] = 0;
    EXPECT_THROW(z_test(input), std::invalid_argument);
    input.test_samples.pop_back();
    EXPECT_THROW(z_test(input), std::invalid_argument);
}

// Two diffuse balls lit by a point light, direct and indirect light path traced; `ball_reflectance` is the left
// ball's material alone. Pixel values near 0.7: the absolute variance floor (1e-4) is small beside them.
std::string two_balls(double ball_reflectance) {
    return R"({"isotrace": 1, "colour": {"working_space": "lin_rec709"},
  "film": {"resolution": [32, 16], "filter": {"type": "box"}, "aovs": ["variance", "sample_count"]},
  "camera": {"type": "perspective", "fov": 40, "look_at": {"eye": [0, 0, 7], "target": [0, 0, 0]}},
  "sampler": {"type": "independent"},
  "integrator": {"type": "path", "max_depth": 4},
  "materials": {"ball": {"type": "diffuse", "reflectance": )" +
           std::to_string(ball_reflectance) + R"(}, "other": {"type": "diffuse", "reflectance": 0.8}},
  "lights": [{"type": "point", "position": [0, 4, 6], "intensity": 250}],
  "objects": [{"material": "ball", "shape": {"type": "sphere", "radius": 1}, "transform": {"translate": [-1.1, 0, 0]}},
              {"material": "other", "shape": {"type": "sphere", "radius": 1}, "transform": {"translate": [1.1, 0, 0]}}]})";
}

ImageBuffer render(const std::string& text, int spp, std::uint64_t seed) {
    const testing::SceneFile file(text, "z_test");
    SceneOverrides overrides;
    overrides.spp = spp;
    overrides.seed = seed;
    const auto scene = load_scene(file.path(), overrides);
    RenderOptions options;
    options.spp = spp;
    return render_scene(*scene, options).film->resolve();
}

// Channels of a resolved film: R G B A variance.R variance.G variance.B sampleCount.
ZTestInput from_renders(const ImageBuffer& reference, const ImageBuffer& test, float brightness) {
    ZTestInput input;
    input.reference_mean = RgbImage(reference.width, reference.height);
    input.reference_variance = RgbImage(reference.width, reference.height);
    input.test = RgbImage(test.width, test.height);
    const std::size_t stride = reference.channels.size();
    for (std::size_t i = 0; i < input.test.pixel_count(); ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            input.reference_mean.values[3 * i + c] = reference.pixels[i * stride + c];
            input.reference_variance.values[3 * i + c] = reference.pixels[i * stride + 4 + c];
            input.test.values[3 * i + c] = brightness * test.pixels[i * stride + c];
        }
        input.reference_samples.push_back(reference.pixels[i * stride + 7]);
        input.test_samples.push_back(test.pixels[i * stride + 7]);
    }
    return input;
}

// The reference at 1024 spp, the test at 64 spp with another seed.
TEST(ZTest, UnbiasedRenderPassesAndTwoPercentBrighterFails) {
    const ImageBuffer reference = render(two_balls(0.5), 1024, 1);
    const ImageBuffer test = render(two_balls(0.5), 64, 2);
    ASSERT_EQ(reference.channels.size(), 8u);
    ASSERT_EQ(reference.channels[7], "sampleCount");
    const ZTestResult unbiased = z_test(from_renders(reference, test, 1.0f));
    EXPECT_TRUE(unbiased.passed) << unbiased.pass_fraction;
    const ZTestResult biased = z_test(from_renders(reference, test, 1.02f));
    EXPECT_FALSE(biased.passed) << biased.pass_fraction;
}

TEST(ZTest, TwoPercentBrighterMaterialFails) {
    // The left ball's reflectance 0.51 instead of 0.5 in the test render (64 spp, another seed) fails against the
    // 1024-spp reference.
    const ImageBuffer reference = render(two_balls(0.5), 1024, 1);
    const ZTestResult biased = z_test(from_renders(reference, render(two_balls(0.51), 64, 2), 1.0f));
    EXPECT_FALSE(biased.passed) << biased.pass_fraction;
    EXPECT_GT(biased.failed_channels, 10);
}

}  // namespace
}  // namespace isotrace
