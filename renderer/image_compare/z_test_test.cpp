// The z-test: worked numbers on synthetic images (pixels alone, the Welch variance, the block levels), then real
// renders — an unbiased low-budget render passes against a reference with another seed; the same render 2 %
// too bright fails, and so does a render with one material 2 % brighter; on the Cornell box the 2 % brighter
// image passes every pixel test and is caught by the block tests.
#include "renderer/image_compare/z_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

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

ZTestSettings pixels_only() {
    ZTestSettings settings;
    settings.block_edges = {};
    return settings;
}

TEST(ZTest, SidakCorrectedSignificance) {
    // alpha = 1 - 0.99^(1/300) for 100 pixels x 3 channels.
    const ZTestResult result = z_test(uniform_input(10, 10, 1, 0.01f, 100, 1, 4), pixels_only());
    ASSERT_EQ(result.levels.size(), 1u);
    EXPECT_NEAR(result.pixels().alpha, 1 - std::pow(0.99, 1.0 / 300), 1e-15);
    EXPECT_TRUE(result.passed);
    EXPECT_EQ(result.pixels().pass_fraction, 1.0);
}

TEST(ZTest, LevelsShareTheSignificance) {
    // 40x24: pixels, 4x4 blocks (10 x 6), 16x16 blocks (3 x 2, clipped at the border), then one block, the whole
    // image (64 covers it and is cut to 40). Each level gets 0.01 / 4 and is Sidak-corrected over its tests.
    const ZTestResult result = z_test(uniform_input(40, 24, 1, 0.01f, 100, 1, 4));
    ASSERT_EQ(result.levels.size(), 4u);
    const int edges[] = {1, 4, 16, 40};
    const int tests[] = {3 * 960, 3 * 60, 3 * 6, 3};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(result.levels[i].edge, edges[i]);
        EXPECT_EQ(result.levels[i].tests, tests[i]);
        EXPECT_NEAR(result.levels[i].alpha, 1 - std::pow(1 - 0.0025, 1.0 / tests[i]), 1e-15);
    }
    EXPECT_TRUE(result.passed);
}

TEST(ZTest, ZStatisticWorkedByHand) {
    // Reference variance of the mean 0.0001 at 100 spp: per-sample variance 0.01. Test at 4 spp:
    // standard error sqrt(0.01 / 4 + 0.01 / 100) = 0.0509902; a difference of 0.25 is z = 4.90290, two-sided
    // p = erfc(4.90290 / sqrt 2) = 9.44e-7 < alpha (3.35e-5 for 300 channels): every channel fails.
    const ZTestResult far = z_test(uniform_input(10, 10, 1, 1e-4f, 100, 1.25f, 4), pixels_only());
    EXPECT_NEAR(far.pixels().min_p_value, std::erfc(0.25 / std::sqrt(0.01 / 4 + 0.01 / 100) / std::sqrt(2.0)), 1e-9);
    EXPECT_EQ(far.pixels().failed, 300);
    EXPECT_FALSE(far.passed);
    ASSERT_EQ(far.worst.size(), 12u);  // the listing is cut at 12
    EXPECT_NEAR(far.worst[0].z, 0.25 / std::sqrt(0.01 / 4 + 0.01 / 100), 1e-5);
    EXPECT_NEAR(far.worst[0].test, 1.25, 1e-6);
    EXPECT_NEAR(far.worst[0].reference, 1.0, 1e-6);
    // A difference of 0.15 is z = 2.94 (p = 0.0033 > alpha): all pass.
    EXPECT_TRUE(z_test(uniform_input(10, 10, 1, 1e-4f, 100, 1.15f, 4), pixels_only()).passed);
}

TEST(ZTest, TestVarianceCountsWhenLargerThanTheReferences) {
    // The same far case, but the test says its mean has variance 0.01 at 4 spp: per-sample variance 0.04, more
    // than the reference's 0.01, so the standard error is sqrt(0.04 / 4 + 0.01 / 100) = 0.100499: z = 2.4876,
    // p = 0.01286 > alpha, and every channel passes (a noisier renderer is judged by its own noise).
    ZTestInput input = uniform_input(10, 10, 1, 1e-4f, 100, 1.25f, 4);
    input.test_variance = RgbImage(10, 10, 0.01f);
    const ZTestResult noisier = z_test(input, pixels_only());
    EXPECT_NEAR(noisier.pixels().min_p_value, std::erfc(0.25 / std::sqrt(0.04 / 4 + 0.01 / 100) / std::sqrt(2.0)), 1e-7);
    EXPECT_TRUE(noisier.passed);
    // A test variance below the reference's is raised to it: the verdict is the one without it.
    input.test_variance = RgbImage(10, 10, 1e-6f);
    EXPECT_EQ(z_test(input, pixels_only()).pixels().failed, 300);
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
    EXPECT_TRUE(z_test(input, pixels_only()).passed);
    input.test.values[0] = 5;
    const ZTestResult one = z_test(input, pixels_only());
    EXPECT_EQ(one.pixels().failed, 1);
    EXPECT_FALSE(one.passed);
    EXPECT_EQ(one.failed_per_pixel[0], 1.0f);
    ASSERT_EQ(one.worst.size(), 1u);
    EXPECT_EQ(one.worst[0].x, 0);
    EXPECT_EQ(one.worst[0].channel, 0);
}

TEST(ZTest, BlocksFindASmallUniformBiasThatPixelsMiss) {
    // Reference: mean 1 at 1024 spp, per-sample variance 0.1024; test 2 % brighter at 64 spp. Per pixel the
    // standard error is sqrt(0.1024 / 64 + 0.1024 / 1024) = 0.0412: z = 0.49, no pixel fails. Over a 16x16 block
    // it is 16 times smaller (z = 7.8), over the whole 32x32 image 32 times (z = 15.5): both fail.
    const ZTestResult result = z_test(uniform_input(32, 32, 1, 1e-4f, 1024, 1.02f, 64));
    ASSERT_EQ(result.levels.size(), 4u);
    EXPECT_EQ(result.pixels().failed, 0);
    EXPECT_TRUE(result.levels[1].passed);  // 4x4: z = 1.9
    EXPECT_EQ(result.levels[2].failed, 12);
    EXPECT_EQ(result.levels[3].failed, 3);
    EXPECT_FALSE(result.passed);
    EXPECT_EQ(result.worst.front().edge, 32);
    EXPECT_NEAR(result.worst.front().z, 0.02 / (0.0412311 / 32), 1e-3);
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

ImageBuffer render_file(const std::string& path, int spp, std::uint64_t seed, std::optional<RasterSize> resolution = {}) {
    SceneOverrides overrides;
    overrides.settings.push_back(spp_setting(spp));
    overrides.settings.push_back(seed_setting(seed));
    if (resolution) overrides.settings.push_back(resolution_setting(*resolution));
    overrides.extra_aovs = {Aov::Variance, Aov::SampleCount};  // what isotrace render --reference adds
    const auto scene = load_scene(path, overrides);
    RenderOptions options;
    options.spp = spp;
    return render_scene(*scene, options).film->resolve();
}

ImageBuffer render(const std::string& text, int spp, std::uint64_t seed) {
    const testing::SceneFile file(text, "z_test");
    return render_file(file.path(), spp, seed);
}

// Channels of a resolved film: R G B A variance.R variance.G variance.B sampleCount. The test image scaled by
// `brightness` (its variance by brightness^2), as if its renderer were that much too bright.
ZTestInput from_renders(const ImageBuffer& reference, const ImageBuffer& test, float brightness) {
    ZTestInput input;
    input.reference_mean = RgbImage(reference.width, reference.height);
    input.reference_variance = RgbImage(reference.width, reference.height);
    input.test = RgbImage(test.width, test.height);
    input.test_variance = RgbImage(test.width, test.height);
    const std::size_t stride = reference.channels.size();
    for (std::size_t i = 0; i < input.test.pixel_count(); ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            input.reference_mean.values[3 * i + c] = reference.pixels[i * stride + c];
            input.reference_variance.values[3 * i + c] = reference.pixels[i * stride + 4 + c];
            input.test.values[3 * i + c] = brightness * test.pixels[i * stride + c];
            input.test_variance.values[3 * i + c] = brightness * brightness * test.pixels[i * stride + 4 + c];
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
    EXPECT_TRUE(unbiased.passed) << unbiased.pixels().pass_fraction;
    const ZTestResult biased = z_test(from_renders(reference, test, 1.02f));
    EXPECT_FALSE(biased.passed) << biased.pixels().pass_fraction;
}

TEST(ZTest, TwoPercentBrighterMaterialFails) {
    // The left ball's reflectance 0.51 instead of 0.5 in the test render (64 spp, another seed) fails against the
    // 1024-spp reference.
    const ImageBuffer reference = render(two_balls(0.5), 1024, 1);
    const ZTestResult biased = z_test(from_renders(reference, render(two_balls(0.51), 64, 2), 1.0f));
    EXPECT_FALSE(biased.passed) << biased.pixels().pass_fraction;
    EXPECT_GT(biased.pixels().failed, 10);
}

// The Cornell box (path traced, 16 bounces) at 32x32: a 1024-spp reference, a 256-spp test with another seed.
// Its noise per pixel is several times 2 %, so no pixel test sees a 2 % brighter image; the block tests do, and
// the unbiased render passes every level.
TEST(ZTest, CornellBoxTwoPercentBrighterIsCaughtByTheBlocks) {
    const std::string scene = ISOTRACE_SCENES_DIR "/cornell_box.json";
    const ImageBuffer reference = render_file(scene, 1024, 1, RasterSize{32, 32});
    const ImageBuffer test = render_file(scene, 256, 2, RasterSize{32, 32});
    const ZTestResult unbiased = z_test(from_renders(reference, test, 1.0f));
    for (const ZTestLevel& level : unbiased.levels)
        EXPECT_TRUE(level.passed) << "block edge " << level.edge << ": " << level.failed << " of " << level.tests;
    EXPECT_TRUE(unbiased.passed);

    const ZTestResult biased = z_test(from_renders(reference, test, 1.02f));
    EXPECT_TRUE(biased.pixels().passed) << biased.pixels().failed << " pixel channels fail";
    EXPECT_FALSE(biased.passed);
    EXPECT_FALSE(biased.levels.back().passed);  // the whole image
}

}  // namespace
}  // namespace isotrace
