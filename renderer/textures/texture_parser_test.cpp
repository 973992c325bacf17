#include "renderer/textures/texture_parser.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

#include "renderer/colour/colour_system.h"
#include "renderer/plugin/shape.h"
#include "renderer/scene/render_scene.h"
#include "tests/support/scene_files.h"
#include "tests/support/test_images.h"

namespace isotrace {
namespace {

const ColourSystem& colours() {
    static const ColourSystem system("", "ACEScg");
    return system;
}

// The images the tests read: a 2x2 float RGB image with known texels, an 8-bit one and a damaged one.
const testing::TemporaryDirectory& images() {
    static const testing::TemporaryDirectory directory("texture_parser");
    static const bool written = [] {
        testing::write_rgb_image(directory / "quad.exr", 2, 2, std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1, 2, 2, 2});
        testing::write_rgb_image(directory / "grey.png", 1, 1, std::vector<std::uint8_t>{128, 128, 128});
        directory.write("corrupt.png", "\x89PNG\r\n\x1a\n this is not a PNG");
        return true;
    }();
    (void)written;
    return directory;
}

struct Scene {
    explicit Scene(const std::string& json) : parsed(json, &colours(), images().path()) {}
    const SceneNode& root() const { return parsed.root(); }
    testing::ParsedScene parsed;
};

// The texel centres of quad.exr: (0, 0) top left.
TextureContext at_texel(int x, int y) {
    TextureContext context;
    context.uv = {(float(x) + 0.5f) / 2, 1 - (float(y) + 0.5f) / 2};
    return context;
}

struct ErrorSeen {
    SourceLocation where;
    std::string field;
    std::string message;
};

ErrorSeen error_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const InputError& error) {
        return {error.location(), error.field(), error.what()};
    }
    ADD_FAILURE() << "no InputError";
    return {};
}

void expect_error(const std::function<void()>& action, int line, const std::string& field, const std::string& part) {
    const ErrorSeen seen = error_of(action);
    EXPECT_EQ(seen.where.file, "scene.json") << seen.message;
    EXPECT_EQ(seen.where.line, line) << seen.message;
    EXPECT_GT(seen.where.column, 0) << seen.message;
    EXPECT_EQ(seen.field, field) << seen.message;
    EXPECT_NE(seen.message.find(part), std::string::npos) << seen.message;
}

ScalarTexturePtr scalar(const Scene& scene, const std::string& key, NumberRange range = {}) {
    return parse_scalar_texture(scene.root(), key, 0.5f, range);
}
ColourTexturePtr colour(const Scene& scene, const std::string& key, ColourRange range = ColourRange::Any) {
    return parse_colour_texture(scene.root(), key, Rgb(0.5f), range);
}

TEST(TextureParser, Constants) {
    const Scene scene(R"({"n": 0.25, "c": [0.1, 0.2, 0.3], "g": 0.75, "s": {"rgb": [1, 0, 0], "space": "ACEScg"}})");
    EXPECT_EQ(scalar(scene, "n")->constant(), 0.25f);
    EXPECT_EQ(scalar(scene, "absent")->constant(), 0.5f);
    EXPECT_EQ(colour(scene, "c")->constant(), Rgb(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(colour(scene, "g")->constant(), Rgb(0.75f));  // a number is a grey
    EXPECT_EQ(colour(scene, "s")->constant(), Rgb(1, 0, 0));
    EXPECT_EQ(colour(scene, "absent")->constant(), Rgb(0.5f));
    EXPECT_EQ(parse_data_texture(scene.root(), "absent"), nullptr);
}

TEST(TextureParser, ExpressionsOfConstantsFold) {
    const Scene scene(R"({"m": {"type": "mix", "a": 1, "b": 3, "t": 0.25},
        "s": {"type": "scale", "value": [1, 2, 3], "by": 0.5},
        "o": {"type": "offset", "value": {"type": "invert", "value": 0.25}, "by": 0.125}})");
    EXPECT_EQ(scalar(scene, "m")->constant(), 1.5f);
    EXPECT_EQ(colour(scene, "s")->constant(), Rgb(0.5f, 1, 1.5f));
    EXPECT_EQ(scalar(scene, "o")->constant(), 0.875f);
}

TEST(TextureParser, ImagesByEveryForm) {
    const Scene scene(R"({"short": {"texture": "quad.exr", "scale": 0.5},
        "long": {"type": "image", "file": "quad.exr", "wrap": "clamp"},
        "red": {"type": "image", "file": "quad.exr", "channel": "r"},
        "lum": {"type": "image", "file": "quad.exr", "channel": "luminance"},
        "srgb": {"texture": "grey.png"}, "data": {"texture": "grey.png"}})");
    const ColourTexturePtr short_form = colour(scene, "short");
    EXPECT_FALSE(short_form->constant());
    EXPECT_EQ(short_form->evaluate(at_texel(0, 0)), Rgb(0.5f, 0, 0));
    EXPECT_EQ(short_form->evaluate(at_texel(1, 1)), Rgb(1, 1, 1));
    const ColourTexturePtr image = colour(scene, "long");
    EXPECT_EQ(image->evaluate(at_texel(1, 0)), Rgb(0, 1, 0));
    EXPECT_EQ(image->evaluate(at_texel(0, 1)), Rgb(0, 0, 1));
    TextureContext beyond;
    beyond.uv = {1.5f, 0.75f};  // right of the top row: clamped to its last texel
    EXPECT_EQ(image->evaluate(beyond), Rgb(0, 1, 0));
    EXPECT_EQ(scalar(scene, "red")->evaluate(at_texel(0, 0)), 1.0f);
    EXPECT_EQ(scalar(scene, "red")->evaluate(at_texel(1, 0)), 0.0f);
    EXPECT_NEAR(scalar(scene, "lum")->evaluate(at_texel(1, 0)), 0.7152f, 1e-6);
    // A colour image is decoded from sRGB; a data image is used as stored.
    const float srgb = colour(scene, "srgb")->evaluate(at_texel(0, 0)).g;
    EXPECT_NEAR(srgb, std::pow((128.0f / 255 + 0.055f) / 1.055f, 2.4f), 1e-3);
    EXPECT_FLOAT_EQ(parse_data_texture(scene.root(), "data")->evaluate(at_texel(0, 0)).g, 128.0f / 255);
}

TEST(TextureParser, VaryingTexturesAreClampedToTheRange) {
    const Scene scene(R"({"red": {"type": "image", "file": "quad.exr", "channel": "r"},
        "bright": {"texture": "quad.exr"}, "open": {"type": "invert", "value": {"type": "image", "file": "quad.exr", "channel": "g"}}})");
    // Texel (1, 1) is 2: a reflectance stops at 1, a unit-interval number too.
    EXPECT_EQ(colour(scene, "bright", ColourRange::Reflectance)->evaluate(at_texel(1, 1)), Rgb(1));
    EXPECT_EQ(colour(scene, "bright", ColourRange::Any)->evaluate(at_texel(1, 1)), Rgb(2));
    EXPECT_EQ(scalar(scene, "red", NumberRange::unit_interval())->evaluate(at_texel(1, 1)), 1.0f);
    // 1 - 2 = -1, in a range open at 0: the nearest float above 0.
    const float open = scalar(scene, "open", NumberRange::positive())->evaluate(at_texel(1, 1));
    EXPECT_GT(open, 0.0f);
    EXPECT_LT(open, 1e-30f);
}

TEST(TextureParser, NeedsNameTheNodeThatNeeds) {
    const Scene scene(R"({"m": {"type": "mix", "a": 0, "b": 1,
        "t": {"type": "image", "file": "quad.exr", "channel": "r"}},
        "f": {"type": "field", "depth": 0.5}, "p": {"type": "image", "file": "quad.exr", "channel": "r",
        "projection": "planar"}})");
    const TextureNeeds uv = scalar(scene, "m")->needs();
    EXPECT_TRUE(uv.uv);
    EXPECT_FALSE(uv.field);
    EXPECT_EQ(uv.where.line, 2);
    EXPECT_EQ(uv.where.file, "scene.json");
    EXPECT_EQ(uv.field_path, "m.t");
    const TextureNeeds field = scalar(scene, "f")->needs();
    EXPECT_TRUE(field.field);
    EXPECT_EQ(field.field_path, "f");
    EXPECT_EQ(field.where.line, 3);
    EXPECT_FALSE(scalar(scene, "p")->needs().uv);
    EXPECT_FALSE(scalar(scene, "absent")->needs().uv);
}

// A ball of radius 2 whose field is 2 - |p| (positive inside), gradient -p/|p|, scaled by 3.
class BallField final : public Shape {
public:
    std::string type_name() const override { return "ball"; }
    std::size_t primitive_count() const override { return 1; }
    Bounds3f bounds() const override { return {}; }
    bool can_bake(const Transform&) const override { return false; }
    void bake(const Transform&) override {}
    RTCGeometry create_geometry(RTCDevice) override { return nullptr; }
    std::optional<double> field_value(const Vec3d& p) const override { return 2 - length(p); }
    Vec3d field_gradient(const Vec3d& p) const override { return p * (-3 / length(p)); }
};

TEST(TextureParser, FieldReadsTheShapeInsideTheSurface) {
    const Scene scene(R"({"v": {"type": "field", "depth": 0.5}, "g": {"type": "field", "output": "gradient"}})");
    SceneObject object;
    object.shape = std::make_unique<BallField>();
    object.instanced = true;
    object.to_world = Transform::scale({2, 2, 2});  // world radius 4
    SurfaceHit hit;
    hit.position = {4, 0, 0};
    hit.shading_normal = hit.geometric_normal = {1, 0, 0};
    hit.object = &object;
    const TextureContext context(hit);
    EXPECT_NEAR(scalar(scene, "v")->evaluate(context), 0.5, 1e-6);  // 0.5 inward from the surface at |p| = 2
    EXPECT_NEAR(scalar(scene, "g")->evaluate(context), 3, 1e-6);
    EXPECT_EQ(scalar(scene, "v")->evaluate(TextureContext{}), 0.0f);  // no shape
}

TEST(TextureParser, SameResultsOnEveryThread) {
    const Scene scene(R"({"t": {"type": "mix", "a": {"texture": "quad.exr"}, "b": [0.1, 0.9, 0.3],
        "t": {"type": "image", "file": "quad.exr", "channel": "g", "wrap": "mirror",
              "projection": {"type": "triplanar", "transform": {"scale": 0.3}}}}})");
    const ColourTexturePtr texture = colour(scene, "t");
    const auto context = [](int i) {
        TextureContext c;
        c.uv = {std::sin(float(i)) * 2, std::cos(float(i) * 0.7f)};
        c.position = c.object_position = {float(i % 17) * 0.1f, float(i % 5), std::sin(float(i))};
        c.normal = c.object_normal = normalize(Vec3f(std::sin(float(i)), 1, std::cos(float(i) * 3)));
        c.footprint = c.object_footprint = float(i % 7) * 0.05f;
        c.dpdu = {1, 0, 0};
        c.dpdv = {0, 1, 0};
        return c;
    };
    constexpr int kCount = 4000;
    std::vector<Rgb> expected;
    for (int i = 0; i < kCount; ++i) expected.push_back(texture->evaluate(context(i)));
    std::vector<std::vector<Rgb>> seen(4, std::vector<Rgb>(kCount));
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < seen.size(); ++t)
        threads.emplace_back([&, t] {
            for (int k = 0; k < kCount; ++k) {
                const int i = (k * 7 + int(t) * 1013) % kCount;
                seen[t][std::size_t(i)] = texture->evaluate(context(i));
            }
        });
    for (auto& thread : threads) thread.join();
    for (const auto& values : seen) EXPECT_EQ(values, expected);
}

// --- errors: file, line, column, JSON path and what is wrong -------------------------------------------------

TEST(TextureParser, UnknownTypeSuggestsTheNearest) {
    const Scene scene("{\n\"c\": {\"type\": \"imgae\", \"file\": \"quad.exr\"}}");
    expect_error([&] { colour(scene, "c"); }, 2, "c.type", "unknown texture type \"imgae\" (did you mean \"image\"?)");
}

TEST(TextureParser, UnknownKeySuggestsTheNearest) {
    const Scene scene("{\"c\": {\"type\": \"image\", \"file\": \"quad.exr\",\n \"wrapp\": \"clamp\"}}");
    expect_error([&] { colour(scene, "c"); }, 2, "c.wrapp", "unknown key \"wrapp\" (did you mean \"wrap\"?)");
}

TEST(TextureParser, ScalarImageNeedsAChannelAndColourImageRefusesOne) {
    const Scene scene("{\"s\": {\"type\": \"image\", \"file\": \"quad.exr\"},\n"
                      "\"c\": {\"type\": \"image\", \"file\": \"quad.exr\", \"channel\": \"r\"},\n"
                      "\"short\": {\"texture\": \"quad.exr\"},\n"
                      "\"space\": {\"type\": \"image\", \"file\": \"quad.exr\", \"channel\": \"r\", \"space\": \"ACEScg\"}}");
    expect_error([&] { scalar(scene, "s"); }, 1, "s", "needs \"channel\": one of r, g, b, a, luminance");
    expect_error([&] { colour(scene, "c"); }, 2, "c.channel", "a colour takes the image's RGB");
    expect_error([&] { scalar(scene, "short"); }, 3, "short", "this parameter is a number, not a colour");
    expect_error([&] { scalar(scene, "space"); }, 4, "space.space", "no colour space");
}

TEST(TextureParser, ColourForANumberIsRefusedNumberForAColourIsGrey) {
    const Scene scene("{\"a\": [0.1, 0.2, 0.3],\n\"b\": {\"rgb\": [1, 1, 1], \"space\": \"ACEScg\"},\n\"g\": 0.5}");
    expect_error([&] { scalar(scene, "a"); }, 1, "a", "this parameter is a number, not a colour");
    expect_error([&] { scalar(scene, "b"); }, 2, "b", "this parameter is a number, not a colour");
    EXPECT_EQ(colour(scene, "g")->constant(), Rgb(0.5f));
}

TEST(TextureParser, ConstantsOutsideTheRangeAreRefused) {
    const Scene scene("{\"neg\": -0.5,\n\"big\": {\"type\": \"scale\", \"value\": 1e30, \"by\": 1e30},\n\"mix\": {\"type\": \"mix\", \"a\": 1, \"b\": 3, \"t\": 0.5},\n"
                      "\"refl\": [0.5, 1.5, 0.5],\n\"reflmix\": {\"type\": \"scale\", \"value\": 0.8, \"by\": 2}}");
    expect_error([&] { scalar(scene, "neg", NumberRange::non_negative()); }, 1, "neg", "out of range: must be >= 0");
    expect_error([&] { scalar(scene, "big"); }, 2, "big", "overflows a float");
    expect_error([&] { colour(scene, "big"); }, 2, "big", "overflows a float");
    expect_error([&] { scalar(scene, "mix", NumberRange::unit_interval()); }, 3, "mix", "value 2 is out of range");
    expect_error([&] { colour(scene, "refl", ColourRange::Reflectance); }, 4, "refl", "must lie in [0, 1]");
    expect_error([&] { colour(scene, "reflmix", ColourRange::Reflectance); }, 5, "reflmix", "must lie in [0, 1]");
    EXPECT_EQ(colour(scene, "refl", ColourRange::Any)->constant(), Rgb(0.5f, 1.5f, 0.5f));
}

TEST(TextureParser, MissingAndCorruptImagesAreErrorsAtTheFile) {
    const Scene scene("{\"m\": {\"type\": \"image\",\n\"file\": \"missing.png\"},\n"
                      "\"c\": {\"texture\":\n\"corrupt.png\"}}");
    expect_error([&] { colour(scene, "m"); }, 2, "m.file", "missing.png");
    expect_error([&] { colour(scene, "c"); }, 4, "c.texture", "corrupt.png");
}

TEST(TextureParser, FieldIsANumberNotAColour) {
    const Scene scene("{\"c\": {\"type\": \"mix\", \"a\": 0, \"b\": 1,\n\"t\": {\"type\": \"field\"}},\n"
                      "\"bad\": {\"type\": \"field\"}}");
    EXPECT_TRUE(colour(scene, "c")->needs().field);  // as a mix's t it is fine
    expect_error([&] { colour(scene, "bad"); }, 3, "bad.type", "\"field\" gives a number, not a colour");
}

TEST(TextureParser, NestingIsBounded) {
    std::string deep = "0.5";
    for (int i = 0; i < 40; ++i) deep = "{\"type\": \"invert\", \"value\": " + deep + "}";
    const Scene scene("{\"deep\": " + deep + "}");
    const ErrorSeen seen = error_of([&] { scalar(scene, "deep"); });
    EXPECT_NE(seen.message.find("nest more than 32 levels"), std::string::npos) << seen.message;
    std::string fine = "0.25";
    for (int i = 0; i < 31; ++i) fine = "{\"type\": \"invert\", \"value\": " + fine + "}";
    EXPECT_EQ(scalar(Scene("{\"fine\": " + fine + "}"), "fine")->constant(), 0.75f);
}

}  // namespace
}  // namespace isotrace
