#include "renderer/params/scene_node.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>

#include "renderer/colour/colour_system.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

namespace fs = std::filesystem;

constexpr double kInf = std::numeric_limits<double>::infinity();

using Scene = testing::ParsedScene;

// The shipped OCIO config with a Linear Rec.709 working space (loaded once; it is immutable).
const ColourSystem& rec709_colours() {
    static const ColourSystem colours(ISOTRACE_SOURCE_CONFIG_DIR "/ocio/isotrace.ocio", "Linear Rec.709 (sRGB)");
    return colours;
}

void expect_error(const std::function<void()>& action, int line, int column, const std::string& field,
                  const std::string& message) {
    testing::expect_input_error(action, "scene.json", line, column, field, message);
}

// --- NumberRange ---------------------------------------------------------------------------------

TEST(NumberRange, ClosedAndOpenEnds) {
    EXPECT_FALSE(NumberRange::positive().contains(0));
    EXPECT_TRUE(NumberRange::positive().contains(1e-300));
    EXPECT_TRUE(NumberRange::non_negative().contains(0));
    EXPECT_FALSE(NumberRange::non_negative().contains(-1e-300));
    EXPECT_TRUE(NumberRange::unit_interval().contains(0));
    EXPECT_TRUE(NumberRange::unit_interval().contains(1));
    EXPECT_FALSE(NumberRange::unit_interval().contains(1.0000001));
    EXPECT_TRUE(NumberRange::at_least(2).contains(2));
    EXPECT_FALSE(NumberRange::at_least(2).contains(1.999));
    const NumberRange open{0, 180, true, true};
    EXPECT_FALSE(open.contains(0));
    EXPECT_FALSE(open.contains(180));
    EXPECT_TRUE(open.contains(179.999));
    const NumberRange half_open{-1, 1, false, true};
    EXPECT_TRUE(half_open.contains(-1));
    EXPECT_FALSE(half_open.contains(1));
}

TEST(NumberRange, NonFiniteIsNeverContained) {
    EXPECT_FALSE(NumberRange{}.contains(kInf));
    EXPECT_FALSE(NumberRange{}.contains(-kInf));
    EXPECT_FALSE(NumberRange{}.contains(std::nan("")));
    EXPECT_FALSE(NumberRange::positive().contains(kInf));
    EXPECT_TRUE(NumberRange{}.contains(-1e308));
}

TEST(NumberRange, Describe) {
    EXPECT_EQ(NumberRange{}.describe(), "finite");
    EXPECT_EQ(NumberRange::positive().describe(), "> 0");
    EXPECT_EQ(NumberRange::non_negative().describe(), ">= 0");
    EXPECT_EQ(NumberRange::at_least(2.5).describe(), ">= 2.5");
    EXPECT_EQ(NumberRange::unit_interval().describe(), "in [0, 1]");
    EXPECT_EQ(NumberRange::between(0.1, 16).describe(), "in [0.1, 16]");
    EXPECT_EQ((NumberRange{0, 180, true, true}.describe()), "in (0, 180)");
    EXPECT_EQ((NumberRange{-1, 1, false, true}.describe()), "in [-1, 1)");
    EXPECT_EQ((NumberRange{-kInf, 5, false, false}.describe()), "<= 5");
    EXPECT_EQ((NumberRange{-kInf, 5, false, true}.describe()), "< 5");
    EXPECT_EQ(NumberRange::between(1, 65536).describe(), "in [1, 65536]");  // no exponent notation
}

// --- Numbers -------------------------------------------------------------------------------------

TEST(SceneNode, RequiredNumber) {
    const Scene scene(R"({"a": 2.5, "s": "x", "film": {"iso": 100}})");
    EXPECT_EQ(scene.root().number("a"), 2.5);
    expect_error([&] { scene.root().number("b"); }, 1, 1, "", "scene.json:1:1: missing required field \"b\"");
    expect_error([&] { scene.root().number("s"); }, 1, 17, "s", "scene.json:1:17: s: expected a number, found string");
    const SceneNode film = scene.root().object("film");
    EXPECT_EQ(film.path(), "film");
    expect_error([&] { film.number("spp"); }, 1, 30, "film", "scene.json:1:30: film: missing required field \"spp\"");
}

TEST(SceneNode, OptionalNumber) {
    const Scene scene(R"({"radius": -1, "scale": 3})");
    EXPECT_EQ(scene.root().number_or("missing", 7.5), 7.5);
    EXPECT_EQ(scene.root().number_or("scale", 7.5, NumberRange::positive()), 3);
    // A present value is checked like a required one.
    expect_error([&] { scene.root().number_or("radius", 1, NumberRange::positive()); }, 1, 12, "radius",
                 "scene.json:1:12: radius: value -1 out of range: must be > 0");
}

TEST(SceneNode, RangeMessages) {
    const Scene scene(R"({"fov": 180, "w": 1.5, "r": 0.05, "n": 123456.789})");
    expect_error([&] { scene.root().number("fov", {0, 180, true, true}); }, 1, 9, "fov",
                 "scene.json:1:9: fov: value 180 out of range: must be in (0, 180)");
    expect_error([&] { scene.root().number("w", NumberRange::unit_interval()); }, 1, 19, "w",
                 "scene.json:1:19: w: value 1.5 out of range: must be in [0, 1]");
    expect_error([&] { scene.root().number("r", NumberRange::between(0.1, 16)); }, 1, 29, "r",
                 "scene.json:1:29: r: value 0.05 out of range: must be in [0.1, 16]");
    expect_error([&] { scene.root().number("n", NumberRange::at_least(1e6)); }, 1, 40, "n",
                 "scene.json:1:40: n: value 123456.789 out of range: must be >= 1000000");
}

TEST(SceneNode, Integers) {
    const Scene scene(R"({"n": 3, "neg": -4, "f": 2.5, "big": 3e9, "e": 1e2})");
    EXPECT_EQ(scene.root().integer("n"), 3);
    EXPECT_EQ(scene.root().integer("neg"), -4);
    EXPECT_EQ(scene.root().integer("e"), 100);
    EXPECT_EQ(scene.root().integer_or("missing", 16), 16);
    EXPECT_EQ(scene.root().integer_or("n", 16, NumberRange::between(1, 8)), 3);
    expect_error([&] { scene.root().integer("f"); }, 1, 26, "f", "scene.json:1:26: f: expected an integer");
    expect_error([&] { scene.root().integer("big"); }, 1, 38, "big", "scene.json:1:38: big: expected an integer");
    expect_error([&] { scene.root().integer_or("n", 1, NumberRange::at_least(4)); }, 1, 7, "n",
                 "scene.json:1:7: n: value 3 out of range: must be >= 4");
}

TEST(SceneNode, UnsignedIntegers) {
    const Scene scene(R"({"max": 9007199254740992, "neg": -1, "half": 1.5, "huge": 1e17, )"
                      R"("top": 18446744073709551615, "over": 18446744073709551616})");
    EXPECT_EQ(scene.root().unsigned_or("max", 0), 9007199254740992ull);
    EXPECT_EQ(scene.root().unsigned_or("missing", 42), 42u);
    expect_error([&] { scene.root().unsigned_or("neg", 0); }, 1, 34, "neg",
                 "scene.json:1:34: neg: value -1 out of range: must be >= 0");
    expect_error([&] { scene.root().unsigned_or("half", 0); }, 1, 46, "half",
                 "scene.json:1:46: half: expected a non-negative integer");
    // Beyond 2^53 only digits say the number exactly.
    EXPECT_EQ(scene.root().unsigned_or("top", 0), 18446744073709551615ull);
    expect_error([&] { scene.root().unsigned_or("huge", 0); }, 1, 59, "huge",
                 "scene.json:1:59: huge: expected a whole number from 0 to 18446744073709551615, written out in digits");
    expect_error([&] { scene.root().unsigned_or("over", 0); }, 1, 102, "over",
                 "scene.json:1:102: over: expected a whole number from 0 to 18446744073709551615, written out in digits");
}

// --- Other scalars -------------------------------------------------------------------------------

TEST(SceneNode, BooleansAndStrings) {
    const Scene scene(R"({"on": true, "off": false, "yes": "yes", "name": "box", "num": 1})");
    EXPECT_TRUE(scene.root().boolean_or("on", false));
    EXPECT_FALSE(scene.root().boolean_or("off", true));
    EXPECT_TRUE(scene.root().boolean_or("missing", true));
    expect_error([&] { scene.root().boolean_or("yes", false); }, 1, 35, "yes",
                 "scene.json:1:35: yes: expected true or false, found string");
    EXPECT_EQ(scene.root().string("name"), "box");
    EXPECT_EQ(scene.root().string_or("missing", "fallback"), "fallback");
    expect_error([&] { scene.root().string("num"); }, 1, 64, "num", "scene.json:1:64: num: expected a string, found number");
    expect_error([&] { scene.root().string("nope"); }, 1, 1, "", "scene.json:1:1: missing required field \"nope\"");
}

TEST(SceneNode, ChoiceWithDidYouMean) {
    const Scene scene(R"({"filter": "gausian", "axis": "y", "far": "zzz"})");
    const std::vector<std::string> filters = {"box", "gaussian", "blackman_harris"};
    expect_error([&] { scene.root().choice_or("filter", "box", filters); }, 1, 12, "filter",
                 "scene.json:1:12: filter: unknown value \"gausian\" (did you mean \"gaussian\"?); "
                 "expected one of: box, gaussian, blackman_harris");
    expect_error([&] { scene.root().choice_or("far", "box", filters); }, 1, 43, "far",
                 "scene.json:1:43: far: unknown value \"zzz\"; expected one of: box, gaussian, blackman_harris");
    EXPECT_EQ(scene.root().choice_or("axis", "x", {"x", "y", "diagonal"}), "y");
    EXPECT_EQ(scene.root().choice_or("missing", "box", filters), "box");
}

// --- Arrays and vectors --------------------------------------------------------------------------

TEST(SceneNode, NumbersOfAGivenCount) {
    const Scene scene(R"({"crop": [0, 0.5, 0.25, 1], "short": [1, 2], "bad": [0, 2, 0, 1], "str": "x"})");
    EXPECT_EQ(scene.root().numbers("crop", 4, NumberRange::unit_interval()), (std::vector<double>{0, 0.5, 0.25, 1}));
    expect_error([&] { scene.root().numbers("short", 4); }, 1, 38, "short",
                 "scene.json:1:38: short: expected an array of 4 numbers");
    expect_error([&] { scene.root().numbers("str", 4); }, 1, 74, "str", "scene.json:1:74: str: expected an array of 4 numbers");
    // Each element is checked at its own position and path.
    expect_error([&] { scene.root().numbers("bad", 4, NumberRange::unit_interval()); }, 1, 57, "bad[1]",
                 "scene.json:1:57: bad[1]: value 2 out of range: must be in [0, 1]");
}

TEST(SceneNode, Vec3) {
    const Scene scene(R"({"eye": [1, -2.5, 3e2], "two": [1, 2], "str": [1, "2", 3]})");
    EXPECT_EQ(scene.root().vec3("eye"), Vec3d(1, -2.5, 300));
    EXPECT_EQ(scene.root().vec3_or("missing", {4, 5, 6}), Vec3d(4, 5, 6));
    expect_error([&] { scene.root().vec3("two"); }, 1, 32, "two",
                 "scene.json:1:32: two: expected an array of 3 numbers [x, y, z]");
    expect_error([&] { scene.root().vec3("str"); }, 1, 51, "str[1]",
                 "scene.json:1:51: str[1]: expected a number, found string");
    expect_error([&] { scene.root().vec3("missing"); }, 1, 1, "", "scene.json:1:1: missing required field \"missing\"");
}

// --- Colours -------------------------------------------------------------------------------------

TEST(SceneNode, ColourAsTripleOrGrey) {
    const Scene scene(R"({"c": [0.1, 0.2, 0.3], "g": 0.18, "s": "red", "short": [1, 2]})");
    EXPECT_EQ(scene.root().colour("c"), Rgb(0.1f, 0.2f, 0.3f));  // already in the working space
    EXPECT_EQ(scene.root().colour("g"), Rgb(0.18f));
    EXPECT_EQ(scene.root().colour_or("missing", Rgb(0.5f)), Rgb(0.5f));
    expect_error([&] { scene.root().colour("s"); }, 1, 40, "s",
                 "scene.json:1:40: s: expected a colour: [r, g, b], a number, or {\"rgb\": [r, g, b], \"space\": name}");
    expect_error([&] { scene.root().colour("short"); }, 1, 56, "short",
                 "scene.json:1:56: short: expected an array of 3 numbers [x, y, z]");
}

TEST(SceneNode, ColourInANamedSpaceIsConvertedToTheWorkingSpace) {
    const Scene scene(R"({"tex": {"rgb": [0.5, 0.5, 0.5], "space": "srgb_texture"},
                          "lin": {"rgb": [0.25, 0.5, 1], "space": "lin_rec709"},
                          "black": {"rgb": [0, 0, 0], "space": "sRGB - Texture"}})",
                      &rec709_colours());
    const Rgb tex = scene.root().colour("tex");
    // ((0.5 + 0.055) / 1.055)^2.4, the sRGB decoding.
    EXPECT_NEAR(tex.r, 0.214041, 2e-5);
    EXPECT_NEAR(tex.g, 0.214041, 2e-5);
    EXPECT_NEAR(tex.b, 0.214041, 2e-5);
    const Rgb lin = scene.root().colour("lin");  // same space as the working space: unchanged
    EXPECT_NEAR(lin.r, 0.25, 1e-6);
    EXPECT_NEAR(lin.g, 0.5, 1e-6);
    EXPECT_NEAR(lin.b, 1.0, 1e-6);
    const Rgb black = scene.root().colour("black");
    EXPECT_NEAR(black.max(), 0.0, 1e-7);
}

TEST(SceneNode, ColourSpaceErrors) {
    const Scene scene(
        "{\"albedo\": {\"rgb\": [1, 1, 1],\n"
        "            \"space\": \"srgb_textur\"},\n"
        " \"extra\": {\"rgb\": [1, 1, 1], \"space\": \"raw\", \"gamma\": 2.2},\n"
        " \"nospace\": {\"rgb\": [1, 1, 1]}}",
        &rec709_colours());
    // The unknown space is reported where its name is written.
    expect_error([&] { scene.root().colour("albedo"); }, 2, 22, "albedo.space",
                 "scene.json:2:22: albedo.space: unknown colour space \"srgb_textur\" (did you mean \"srgb_texture\"?)");
    expect_error([&] { scene.root().colour("extra"); }, 3, 55, "extra.gamma",
                 "scene.json:3:55: extra.gamma: unknown key \"gamma\"; known keys here: rgb, space");
    expect_error([&] { scene.root().colour("nospace"); }, 4, 13, "nospace",
                 "scene.json:4:13: nospace: missing required field \"space\"");

    const Scene no_colours(R"({"c": {"rgb": [1, 1, 1], "space": "srgb_texture"}})");
    expect_error([&] { no_colours.root().colour("c"); }, 1, 7, "c",
                 "scene.json:1:7: c: no colour system available to convert from \"srgb_texture\"");
}

// --- Files ---------------------------------------------------------------------------------------

TEST(SceneNode, FilePathResolvesAgainstTheSceneDirectory) {
    testing::TemporaryDirectory dir("node");
    const fs::path mesh = dir.write("meshes/bunny.obj", "v 0 0 0\n");
    const std::string text = "{\"file\": \"meshes/bunny.obj\", \"abs\": \"" + mesh.string() +
                             "\", \"missing\": \"meshes/nope.obj\", \"dir\": \"meshes\"}";
    const Scene scene(text, nullptr, dir.path());
    EXPECT_EQ(scene.root().file_path("file"), dir.path() / "meshes/bunny.obj");
    EXPECT_EQ(scene.root().file_path("abs"), mesh);
    try {
        scene.root().file_path("missing");
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.field(), "missing");
        EXPECT_EQ(error.location().line, 1);
        EXPECT_EQ(error.location().column, int(text.find("\"meshes/nope.obj\"")) + 1);
        EXPECT_EQ(std::string(error.what()), "scene.json:1:" + std::to_string(error.location().column) +
                                                 ": missing: " + (dir.path() / "meshes/nope.obj").string() +
                                                 ": file not found");
    }
    EXPECT_THROW(scene.root().file_path("dir"), InputError);  // a directory is not a file
}

// --- Structure -----------------------------------------------------------------------------------

TEST(SceneNode, ObjectsArraysAndPaths) {
    const Scene scene(R"({"objects": [{"a": 1}, 5], "list": [1, "x"], "map": {"z": 1, "b": 2}, "n": 3})");
    expect_error([&] { scene.root().object_array("objects"); }, 1, 24, "objects[1]",
                 "scene.json:1:24: objects[1]: expected an object, found number");
    EXPECT_TRUE(scene.root().object_array("missing").empty());
    const std::vector<SceneNode> list = scene.root().optional_value("list")->elements();
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[1].path(), "list[1]");
    EXPECT_EQ(list[1].json().string, "x");
    const SceneNode map = scene.root().object("map");
    EXPECT_EQ(map.keys(), (std::vector<std::string>{"z", "b"}));
    EXPECT_EQ(map.child_path("z"), "map.z");
    EXPECT_EQ(scene.root().child_path("map"), "map");
    expect_error([&] { scene.root().object("n"); }, 1, 76, "n", "scene.json:1:76: n: expected an object, found number");
    expect_error([&] { scene.root().object("list"); }, 1, 36, "list",
                 "scene.json:1:36: list: expected an object, found array");
    EXPECT_FALSE(scene.root().optional_object("missing").has_value());
    EXPECT_FALSE(scene.root().optional_value("missing").has_value());
    expect_error([&] { scene.root().optional_value("n")->elements(); }, 1, 76, "n",
                 "scene.json:1:76: n: expected an array, found number");
}

TEST(SceneNode, FailAtNamesTheValueOrTheNode) {
    const Scene scene(R"({"material": {"reflectance": 2}})");
    const SceneNode material = scene.root().object("material");
    expect_error([&] { material.fail_at("reflectance", "too bright"); }, 1, 30, "material.reflectance",
                 "scene.json:1:30: material.reflectance: too bright");
    expect_error([&] { material.fail_at("absent", "needs it"); }, 1, 14, "material",
                 "scene.json:1:14: material: needs it");
}

TEST(SceneNode, FinishRejectsAnUnknownKeyWithDidYouMean) {
    const Scene scene(
        "{\n"
        "  \"objects\": [\n"
        "    {\"shape\": {\"type\": \"sphere\", \"radius\": 1}},\n"
        "    {\"shape\": {\"type\": \"sphere\",\n"
        "               \"radus\": 2}}\n"
        "  ]\n"
        "}\n");
    const std::vector<SceneNode> objects = scene.root().object_array("objects");
    ASSERT_EQ(objects.size(), 2u);
    const auto read_sphere = [](const SceneNode& shape) {
        shape.string("type");
        shape.vec3_or("center", {0, 0, 0});
        shape.number_or("radius", 1.0, NumberRange::positive());
        shape.finish();
    };
    EXPECT_NO_THROW(read_sphere(objects[0].object("shape")));
    expect_error([&] { read_sphere(objects[1].object("shape")); }, 5, 25, "objects[1].shape.radus",
                 "scene.json:5:25: objects[1].shape.radus: unknown key \"radus\" (did you mean \"radius\"?); "
                 "known keys here: center, radius, type");
}

TEST(SceneNode, FinishWithNothingReadListsNoKnownKeys) {
    const Scene scene(R"({"x": 1})");
    expect_error([&] { scene.root().finish(); }, 1, 7, "x", "scene.json:1:7: x: unknown key \"x\"");
}

TEST(SceneNode, FinishAcceptsReadAndAcceptedKeys) {
    const Scene scene(R"({"a": 1, "m": {"user_name": 1, "other": 2}})");
    scene.root().number("a");
    const SceneNode map = scene.root().object("m");
    map.accept_all_keys();
    EXPECT_NO_THROW(map.finish());
    EXPECT_NO_THROW(scene.root().finish());
    // has() only asks; it does not count as reading the key.
    const Scene asked(R"({"a": 1})");
    EXPECT_TRUE(asked.root().has("a"));
    EXPECT_FALSE(asked.root().has("b"));
    EXPECT_THROW(asked.root().finish(), InputError);
}

// The hint listed only keys read so far: an optional key the plugin merely asked about (film "crop") was missing.
TEST(SceneNode, UnknownKeyHintListsKeysAskedAboutToo) {
    const Scene scene(R"({"a": 1, "crpo": [0, 1, 0, 1]})");
    scene.root().number("a");
    EXPECT_FALSE(scene.root().has("crop"));
    try {
        scene.root().finish();
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("(did you mean \"crop\"?); known keys here: a, crop"), std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace isotrace
