#include "renderer/params/transform_parser.h"

#include <gtest/gtest.h>

#include <functional>

#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

using Scene = testing::ParsedScene;

// parse_optional_transform(root, "transform") of a document.
Transform parse(const std::string& text) {
    const Scene scene(text);
    return parse_optional_transform(scene.root(), "transform");
}

void expect_error(const std::string& text, int line, int column, const std::string& field, const std::string& message) {
    testing::expect_input_error([&] { parse(text); }, "scene.json", line, column, field, message);
}

void expect_error_containing(const std::string& text, int line, int column, const std::string& field,
                             const std::string& part) {
    try {
        parse(text);
        ADD_FAILURE() << "no InputError; expected one containing: " << part;
    } catch (const InputError& error) {
        EXPECT_EQ(error.location().line, line) << error.what();
        EXPECT_EQ(error.location().column, column) << error.what();
        EXPECT_EQ(error.field(), field) << error.what();
        EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
    }
}

void expect_near(const Vec3d& actual, const Vec3d& expected, double tolerance = 1e-12) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "x";
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "y";
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "z";
}

TEST(ParseTransform, AbsentOrEmptyIsIdentity) {
    EXPECT_TRUE(parse(R"({})").is_identity());
    EXPECT_TRUE(parse(R"({"transform": {}})").is_identity());
    EXPECT_TRUE(parse(R"({"transform": []})").is_identity());
}

TEST(ParseTransform, MatrixIsRowMajorWithColumnVectors) {
    const Transform t = parse(R"({"transform": {"matrix": [1, 0, 0, 5,  0, 2, 0, 6,  0, 0, 3, 7,  0, 0, 0, 1]}})");
    EXPECT_EQ(t.point(Vec3d{1, 1, 1}), Vec3d(6, 8, 10));
    EXPECT_EQ(t.vector(Vec3d{1, 1, 1}), Vec3d(1, 2, 3));
    expect_near(t.inverse().point(Vec3d{6, 8, 10}), {1, 1, 1});
}

TEST(ParseTransform, MatrixErrors) {
    expect_error(R"({"transform": {"matrix": [1, 0, 0]}})", 1, 26, "transform.matrix",
                 "scene.json:1:26: transform.matrix: expected an array of 16 numbers");
    expect_error(R"({"transform": {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,1,1]}})", 1, 26, "transform.matrix",
                 "scene.json:1:26: transform.matrix: matrix is not affine: the last row must be [0, 0, 0, 1]");
    expect_error(R"({"transform": {"matrix": [1,0,0,0, 0,1,0,0, 0,0,0,0, 0,0,0,1]}})", 1, 26, "transform.matrix",
                 "scene.json:1:26: transform.matrix: matrix is singular");
    expect_error(R"({"transform": {"matrix": [1,0,0,0, 2,0,0,1, 0,0,1,0, 0,0,0,1]}})", 1, 26, "transform.matrix",
                 "scene.json:1:26: transform.matrix: matrix is singular");
    expect_error(R"({"transform": {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,"x", 0,0,0,1]}})", 1, 51,
                 "transform.matrix[11]", "scene.json:1:51: transform.matrix[11]: expected a number, found string");
    // A matrix cannot be combined with the other forms in one step.
    expect_error(R"({"transform": {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "scale": 2}})", 1, 73,
                 "transform.scale",
                 "scene.json:1:73: transform.scale: unknown key \"scale\"; known keys here: matrix");
}

TEST(ParseTransform, TranslateRotateScaleAreAppliedScaleFirst) {
    // T * R * S: (1, 0, 0) -> scale (2, 0, 0) -> rotate 90 about z (0, 2, 0) -> translate (1, 4, 3).
    const Transform t =
        parse(R"({"transform": {"translate": [1, 2, 3], "rotate": {"axis": [0, 0, 1], "angle": 90}, "scale": 2}})");
    expect_near(t.point(Vec3d{1, 0, 0}), {1, 4, 3});
    // The order of the keys in the file does not matter.
    const Transform u =
        parse(R"({"transform": {"scale": 2, "rotate": {"angle": 90, "axis": [0, 0, 1]}, "translate": [1, 2, 3]}})");
    expect_near(u.point(Vec3d{1, 0, 0}), {1, 4, 3});
}

TEST(ParseTransform, ScaleFormsAndMirrors) {
    EXPECT_EQ(parse(R"({"transform": {"scale": [1, 2, 3]}})").point(Vec3d{1, 1, 1}), Vec3d(1, 2, 3));
    EXPECT_EQ(parse(R"({"transform": {"scale": 0.5}})").point(Vec3d{2, 4, 8}), Vec3d(1, 2, 4));
    EXPECT_DOUBLE_EQ(parse(R"({"transform": {"scale": [-1, 1, 1]}})").determinant(), -1.0);
}

TEST(ParseTransform, RotateByAxisAndAngle) {
    expect_near(parse(R"({"transform": {"rotate": {"axis": [1, 0, 0], "angle": 90}}})").point(Vec3d{0, 1, 0}), {0, 0, 1});
    expect_near(parse(R"({"transform": {"rotate": {"axis": [0, 3, 0], "angle": -90}}})").point(Vec3d{1, 0, 0}), {0, 0, 1});
}

TEST(ParseTransform, RotateByEulerAnglesAboutXThenYThenZ) {
    expect_near(parse(R"({"transform": {"rotate": [0, 90, 0]}})").point(Vec3d{0, 0, 1}), {1, 0, 0});
    // x first: (0, 0, 1) -> (0, -1, 0); then z: -> (1, 0, 0).  (z first would give (0, -1, 0).)
    expect_near(parse(R"({"transform": {"rotate": [90, 0, 90]}})").point(Vec3d{0, 0, 1}), {1, 0, 0});
    // x, then y: (0, 1, 0) -> (0, 0, 1) -> (1, 0, 0).  (y first would give (0, 0, 1).)
    expect_near(parse(R"({"transform": {"rotate": [90, 90, 0]}})").point(Vec3d{0, 1, 0}), {1, 0, 0});
}

TEST(ParseTransform, ListOfStepsIsAppliedFirstToLast) {
    expect_near(parse(R"({"transform": [{"translate": [1, 0, 0]}, {"scale": 2}]})").point(Vec3d{0, 0, 0}), {2, 0, 0});
    expect_near(parse(R"({"transform": [{"scale": 2}, {"translate": [1, 0, 0]}]})").point(Vec3d{0, 0, 0}), {1, 0, 0});
    const Transform three = parse(
        R"({"transform": [{"translate": [1, 0, 0]}, {"rotate": {"axis": [0, 0, 1], "angle": 90}}, {"scale": 3}]})");
    expect_near(three.point(Vec3d{0, 0, 0}), {0, 3, 0});
    expect_near(three.inverse().point(Vec3d{0, 3, 0}), {0, 0, 0});
}

TEST(ParseTransform, ZeroScaleIsRejectedWhereItIsWritten) {
    expect_error(R"({"transform": {"scale": 0}})", 1, 25, "transform.scale",
                 "scene.json:1:25: transform.scale: scale factor is zero");
    expect_error(
        "{\"transform\": [\n"
        "  {\"translate\": [0, 0, 1]},\n"
        "  {\"scale\": [1, 0, 1]}\n"
        "]}",
        3, 13, "transform[1].scale", "scene.json:3:13: transform[1].scale: scale factor is zero");
}

// A scale of 1e-20 along one axis made Embree abort on `ray.valid()` (exit 134); only exact zeros were rejected.
TEST(ParseTransform, IllConditionedTransformsAreRejectedWhereTheyAreWritten) {
    expect_error(R"({"transform": {"scale": [1, 1e-20, 1]}})", 1, 25, "transform.scale",
                 "scene.json:1:25: transform.scale: the transform is ill-conditioned (condition number 1.41e+20, at "
                 "most 1e6 is supported): its scales are too unequal or its matrix is nearly flat");
    expect_error_containing(R"({"transform": {"matrix": [1, 0, 0, 0, 0, 1e-200, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}})", 1, 26,
                 "transform.matrix", "ill-conditioned");
    expect_error_containing(R"({"transform": {"scale": 1e-200}})", 1, 25, "transform.scale", "outside the supported range");
    expect_error_containing(R"({"transform": {"scale": 1e15}})", 1, 25, "transform.scale", "outside the supported range");
    // Two acceptable steps whose product is not.
    expect_error_containing(R"({"transform": [{"scale": [1, 1e-4, 1]}, {"scale": [1, 1e-4, 1]}]})", 1, 15, "transform",
                 "ill-conditioned");
    // Unequal but sane scales stay accepted: a sphere squashed into a coin, micrometre units.
    EXPECT_NO_THROW(parse(R"({"transform": {"scale": [1, 1e-3, 1]}})"));
    EXPECT_NO_THROW(parse(R"({"transform": {"scale": 1e-6}})"));
}

TEST(ParseTransform, RotationErrors) {
    expect_error(R"({"transform": {"rotate": {"axis": [0, 0, 0], "angle": 5}}})", 1, 26, "transform.rotate",
                 "scene.json:1:26: transform.rotate: rotation axis is zero");
    expect_error(R"({"transform": {"rotate": 45}})", 1, 26, "transform.rotate",
                 "scene.json:1:26: transform.rotate: expected {\"axis\": [x, y, z], \"angle\": degrees} or "
                 "[rx, ry, rz] in degrees");
    expect_error(R"({"transform": {"rotate": {"axis": [0, 0, 1]}}})", 1, 26, "transform.rotate",
                 "scene.json:1:26: transform.rotate: missing required field \"angle\"");
    expect_error(R"({"transform": {"rotate": {"axis": [0, 0, 1], "angle": 5, "degrees": 5}}})", 1, 69,
                 "transform.rotate.degrees",
                 "scene.json:1:69: transform.rotate.degrees: unknown key \"degrees\"; known keys here: angle, axis");
    expect_error(R"({"transform": {"rotate": [1, 2]}})", 1, 26, "transform.rotate",
                 "scene.json:1:26: transform.rotate: expected an array of 3 numbers [x, y, z]");
}

TEST(ParseTransform, StepErrors) {
    expect_error(R"({"transform": {"translate": [1, 2, 3], "scael": 2}})", 1, 49, "transform.scael",
                 "scene.json:1:49: transform.scael: unknown key \"scael\" (did you mean \"scale\"?); "
                 "known keys here: matrix, rotate, scale, translate");
    expect_error(R"({"transform": [{"scale": 1}, 5]})", 1, 30, "transform[1]",
                 "scene.json:1:30: transform[1]: expected a transform object");
    expect_error(R"({"transform": "identity"})", 1, 15, "transform",
                 "scene.json:1:15: transform: expected a transform object");
    expect_error(R"({"transform": {"translate": [1, 2]}})", 1, 29, "transform.translate",
                 "scene.json:1:29: transform.translate: expected an array of 3 numbers [x, y, z]");
}

}  // namespace
}  // namespace isotrace
