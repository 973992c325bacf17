#include "renderer/textures/pattern_texture.h"

#include <gtest/gtest.h>

#include "renderer/textures/texture_parser.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

TextureContext at_point(const Vec3f& p, float footprint = 0) {
    TextureContext context;
    context.position = context.object_position = p;
    context.normal = context.object_normal = {0, 0, 1};
    context.footprint = context.object_footprint = footprint;
    return context;
}

TEST(PatternTexture, CheckerMixesAAndB) {
    const testing::ParsedScene scene(R"({"c": {"type": "checker", "a": [1, 0, 0], "b": [0, 0, 1]},
        "s": {"type": "checker"}, "f": {"type": "checker", "scale": [2, 1, 1]},
        "p": {"type": "checker", "projection": "planar"}})");
    const ColourTexturePtr c = parse_colour_texture(scene.root(), "c", Rgb(0), ColourRange::Any);
    EXPECT_EQ(c->evaluate(at_point({0.25f, 0.25f, 0.25f})), Rgb(1, 0, 0));
    EXPECT_EQ(c->evaluate(at_point({1.25f, 0.25f, 0.25f})), Rgb(0, 0, 1));
    EXPECT_EQ(c->evaluate(at_point({1.25f, 0.25f, 0.25f}, 1000)), Rgb(0.5f, 0, 0.5f));  // filtered to the mean
    const ScalarTexturePtr s = parse_scalar_texture(scene.root(), "s", 0, {});
    EXPECT_EQ(s->evaluate(at_point({1.25f, 1.25f, 0.25f})), 0.0f);
    EXPECT_EQ(s->evaluate(at_point({1.25f, 1.25f, 1.25f})), 1.0f);
    // A frequency of 2 along x: x = 0.6 is in the second cell.
    EXPECT_EQ(parse_scalar_texture(scene.root(), "f", 0, {})->evaluate(at_point({0.6f, 0.25f, 0.25f})), 1.0f);
    // A planar lookup is a 2-D checker: z does not count.
    EXPECT_EQ(parse_scalar_texture(scene.root(), "p", 0, {})->evaluate(at_point({0.25f, 0.25f, 5.5f})), 0.0f);
    EXPECT_EQ(s->evaluate(at_point({0.25f, 0.25f, 5.5f})), 1.0f);
}

TEST(PatternTexture, EachPatternWithItsSettings) {
    const testing::ParsedScene scene(R"({
        "grid": {"type": "grid", "line_width": 0.5},
        "noise": {"type": "noise", "basis": "simplex", "seed": 3},
        "fbm": {"type": "fbm", "octaves": 3, "lacunarity": 2.5, "gain": 0.4, "seed": 7},
        "turbulence": {"type": "turbulence"}, "ridged": {"type": "ridged"},
        "cellular": {"type": "cellular", "jitter": 0, "output": "f1"},
        "ramp": {"type": "ramp", "shape": "linear"}})");
    const auto at = [&](const std::string& key, const Vec3f& p) {
        return parse_scalar_texture(scene.root(), key, 0, {})->evaluate(at_point(p));
    };
    EXPECT_EQ(at("grid", {0.1f, 0.5f, 0.5f}), 1.0f);  // within 0.25 of x = 0
    EXPECT_EQ(at("grid", {0.5f, 0.5f, 0.5f}), 0.0f);
    EXPECT_NEAR(at("cellular", {0.5f, 0.5f, 0.5f}), 0.0f, 1e-6);  // a regular grid's feature point
    EXPECT_NEAR(at("cellular", {0.0f, 0.5f, 0.5f}), 0.5f, 1e-6);
    EXPECT_NEAR(at("ramp", {0.3f, 7, 7}), 0.3f, 1e-6);
    for (const char* key : {"noise", "fbm", "turbulence", "ridged"}) {
        float low = 1, high = 0;
        for (int i = 0; i < 500; ++i) {
            const float v = at(key, {float(i) * 0.173f, float(i % 13) * 0.31f, float(i % 7) * 0.7f});
            low = std::min(low, v);
            high = std::max(high, v);
        }
        EXPECT_GE(low, 0.0f) << key;  // noise and fBm are mapped from [-1, 1]
        EXPECT_LE(high, 1.0f) << key;
        EXPECT_GT(high - low, 0.2f) << key;  // and vary
    }
    // The seed selects another field.
    const testing::ParsedScene seeds(R"({"a": {"type": "noise", "seed": 1}, "b": {"type": "noise", "seed": 2}})");
    EXPECT_NE(parse_scalar_texture(seeds.root(), "a", 0, {})->evaluate(at_point({0.3f, 0.4f, 0.5f})),
              parse_scalar_texture(seeds.root(), "b", 0, {})->evaluate(at_point({0.3f, 0.4f, 0.5f})));
}

TEST(PatternTexture, BadSettingsAreRefusedWhereWritten) {
    const testing::ParsedScene scene("{\"o\": {\"type\": \"fbm\",\n\"octaves\": 30},\n"
                                     "\"k\": {\"type\": \"fbm\", \"octave\": 3},\n\"t\": {\"type\": \"chekcer\"},\n"
                                     "\"s\": {\"type\": \"noise\", \"scale\": -1}}");
    const auto message = [&](const std::string& key) -> std::string {
        try {
            parse_scalar_texture(scene.root(), key, 0, {});
        } catch (const InputError& error) {
            return error.what();
        }
        return "no error";
    };
    EXPECT_NE(message("o").find("scene.json:2:12: o.octaves: value 30 out of range"), std::string::npos) << message("o");
    EXPECT_NE(message("k").find("k.octave: unknown key \"octave\" (did you mean \"octaves\"?)"), std::string::npos)
        << message("k");
    EXPECT_NE(message("t").find("t.type: unknown texture type \"chekcer\" (did you mean \"checker\"?)"), std::string::npos)
        << message("t");
    EXPECT_NE(message("s").find("s.scale: value -1 out of range"), std::string::npos) << message("s");
}

}  // namespace
}  // namespace isotrace
