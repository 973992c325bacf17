// The warnings about a render: a beauty black everywhere or with pixels that are not finite (counted), and the
// light an integrator leaves out of a scene (the preview integrator: an environment seen by rays that leave the
// scene, emissive objects that cannot be sampled as lights).
#include "tools/cli/render_warnings.h"

#include <gtest/gtest.h>

#include <limits>

#include "renderer/scene/loaded_scene.h"
#include "tests/support/scene_files.h"

namespace isotrace::cli {
namespace {

// A 3 x 1 image with channels R, G, B, A, Z; pixel i's beauty is rgb[i].
ImageBuffer image_of(const std::vector<std::array<float, 3>>& rgb) {
    ImageBuffer image;
    image.width = int(rgb.size());
    image.height = 1;
    image.channels = {"R", "G", "B", "A", "Z"};
    for (const auto& [r, g, b] : rgb) image.pixels.insert(image.pixels.end(), {r, g, b, 1.0f, 5.0f});
    return image;
}

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInfinity = std::numeric_limits<float>::infinity();

TEST(RenderWarnings, CountsPixelsWithANaNOrInfiniteBeautyChannel) {
    const BeautyCheck check = check_beauty(image_of({{kNaN, 0, 0}, {0.5f, 0.5f, 0.5f}, {0, kInfinity, 1}}));
    EXPECT_EQ(check.pixels, 3u);
    EXPECT_EQ(check.non_finite_pixels, 2u);
    EXPECT_FALSE(check.all_black);
    const std::vector<std::string> warnings = beauty_warnings(check);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "2 of 3 pixels are NaN or infinite");
}

TEST(RenderWarnings, AnImageBlackInEveryBeautyChannelIsReportedWhateverItsOtherChannels) {
    const BeautyCheck check = check_beauty(image_of({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}));
    EXPECT_TRUE(check.all_black);
    const std::vector<std::string> warnings = beauty_warnings(check);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("black everywhere"), std::string::npos) << warnings[0];
}

TEST(RenderWarnings, OneLitPixelIsNotBlackAndAWellImageHasNoWarning) {
    const BeautyCheck check = check_beauty(image_of({{0, 0, 0}, {0, 0, 1e-6f}, {0, 0, 0}}));
    EXPECT_FALSE(check.all_black);
    EXPECT_TRUE(beauty_warnings(check).empty());
}

TEST(RenderWarnings, NonFinitePixelsAloneAreNotAlsoCalledBlack) {
    const std::vector<std::string> warnings = beauty_warnings(check_beauty(image_of({{kNaN, 0, 0}, {0, 0, 0}})));
    EXPECT_EQ(warnings.size(), 2u);  // the finite pixel is black: both warnings
    EXPECT_EQ(beauty_warnings(check_beauty(image_of({{kNaN, 0, 0}}))).size(), 1u);
}

TEST(RenderWarnings, AnImageWithoutBeautyChannelsIsNotJudged) {
    ImageBuffer depth_only;
    depth_only.width = depth_only.height = 2;
    depth_only.channels = {"Z"};
    depth_only.pixels = {0, 0, 0, 0};
    EXPECT_TRUE(beauty_warnings(check_beauty(depth_only)).empty());
}

std::string scene_with(const std::string& integrator, const std::string& lights, const std::string& emitter) {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "integrator": {"type": ")" + integrator + R"("},
  "materials": {"grey": {"type": "diffuse", "reflectance": 0.5}, "glow": {"type": "emissive", "radiance": 2}},
  "lights": [)" + lights + R"(],
  "objects": [{"material": "grey", "shape": {"type": "sphere", "radius": 1}})" + emitter + "]}";
}

constexpr const char* kPoint = R"({"type": "point", "position": [0, 3, 3], "intensity": 10})";
constexpr const char* kEnvironment = R"({"type": "environment", "radiance": 0.5})";
// A sphere is sampled as an area light; the same sphere in an instance (a transform that cannot be baked into it)
// is not.
constexpr const char* kSampledEmitter =
    R"(, {"material": "glow", "shape": {"type": "sphere", "radius": 0.2}, "transform": {"translate": [2, 0, 0]}})";
// A superquadric cannot draw points on its surface: not a light.
constexpr const char* kUnsampledEmitter =
    R"(, {"material": "glow", "shape": {"type": "superquadric", "radii": [0.2, 0.4, 0.2], "exponents": [1, 1]}})";

std::string warning_for(const std::string& json) {
    const testing::SceneFile file(json);
    return light_left_out_warning(*load_scene(file.path()));
}

TEST(RenderWarnings, ThePreviewOfPointLightsLeavesNothingOut) {
    EXPECT_EQ(warning_for(scene_with("preview", kPoint, "")), "");
}

TEST(RenderWarnings, ThePreviewOfAnAreaLightNamesWhatItMisses) {
    const std::string warning = warning_for(scene_with("preview", kPoint, kSampledEmitter));
    EXPECT_NE(warning.find("the reflections and the bounced light of 1 area light(s)"), std::string::npos) << warning;
    EXPECT_EQ(warning.find("cannot be sampled"), std::string::npos) << warning;
}

TEST(RenderWarnings, ThePreviewOfAnEnvironmentNamesItAndSuggestsThePathTracer) {
    const std::string warning = warning_for(scene_with("preview", kEnvironment, ""));
    EXPECT_NE(warning.find("the preview integrator leaves out the environment"), std::string::npos) << warning;
    EXPECT_NE(warning.find(R"("integrator": {"type": "path"})"), std::string::npos) << warning;
}

TEST(RenderWarnings, ThePreviewCountsEmittersThatCannotBeSampledAsLights) {
    const std::string warning =
        warning_for(scene_with("preview", kPoint, kUnsampledEmitter));
    EXPECT_NE(warning.find("the light that 1 emissive object(s) cast on other surfaces"), std::string::npos) << warning;
    EXPECT_EQ(warning.find("environment"), std::string::npos) << warning;
}

TEST(RenderWarnings, BothLeftOutLightsMakeOneWarning) {
    const std::string warning = warning_for(scene_with("preview", kEnvironment, kUnsampledEmitter));
    EXPECT_NE(warning.find("; and the light that 1 emissive object(s)"), std::string::npos) << warning;
}

TEST(RenderWarnings, ThePathTracerLeavesNothingOut) {
    EXPECT_EQ(warning_for(scene_with("path", kEnvironment, kSampledEmitter)), "");
}

}  // namespace
}  // namespace isotrace::cli
