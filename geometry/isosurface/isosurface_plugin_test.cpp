// The "isosurface" plugin as a user writes it: a function with parameters in a container, another shape's field
// as a term, an isosurface operand of CSG, its field for the polygonisers, and the errors of bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geometry/csg/csg_test_support.h"
#include "geometry/isosurface/isosurface_shape.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

std::unique_ptr<Shape> shape_from_json(const std::string& json) {
    const testing::ParsedScene parsed(json);
    return shape_registry().create(parsed.root());
}

std::optional<IsosurfaceShape::Hit> first_hit(const Shape& shape, const Vec3d& o, const Vec3d& d) {
    IsosurfaceWork work;
    return dynamic_cast<const IsosurfaceShape&>(shape).first_hit(~0u, o, d, 0, INFINITY, work);
}

std::string error_of(const std::string& json) {
    try {
        shape_from_json(json);
    } catch (const InputError& error) {
        return error.what();
    }
    return "no error";
}

TEST(IsosurfacePlugin, AFunctionWithParametersIsTracedExactly) {
    const auto shape = shape_from_json(
        R"({"type": "isosurface", "function": "length(p - c) - r", "parameters": {"r": 0.75, "c": 0.5},
            "contained_by": {"box": {"min": [-1, -1, -1], "max": [2, 2, 2]}}})");
    // p − c subtracts 0.5 from every component: a ball of radius 0.75 about (0.5, 0.5, 0.5).
    const auto hit = first_hit(*shape, {0.5, 0.5, -3}, {0, 0, 1});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3.5 - 0.75, 1e-12);
    EXPECT_NEAR(hit->normal.z, -1, 1e-12);
}

TEST(IsosurfacePlugin, AShapesFieldIsATerm) {
    // A lone Kim metaball of radius 1 and weight 1 at threshold 0.5 is a sphere of radius √(1 − ∛0.5), smoothly
    // united with a small ball beside it; along −z through the metaball's centre only the metaball counts.
    const auto shape = shape_from_json(R"json({"type": "isosurface",
        "function": "smin(body(p), length(p - vec(1.2, 0, 0)) - 0.2, 0.05)",
        "fields": {"body": {"type": "blobs", "elements": [{"center": [0, 0, 0], "radius": 1}]}},
        "contained_by": {"sphere": {"radius": 2}}})json");
    const double iso = std::sqrt(1 - std::cbrt(0.5));
    const auto hit = first_hit(*shape, {0, 0, 3}, {0, 0, -1});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3 - iso, 1e-9);
    EXPECT_NEAR(hit->normal.z, 1, 1e-9);
    // The small ball is there too.
    const auto ball = first_hit(*shape, {1.2, 0, 3}, {0, 0, -1});
    ASSERT_TRUE(ball);
    EXPECT_NEAR(ball->t, 3 - 0.2, 1e-9);
}

TEST(IsosurfacePlugin, IsACsgOperandAndHasAField) {
    using namespace csg_test;
    const auto scene = scene_of(shape_from_json(R"({"type": "csg", "op": "difference", "children": [
        {"shape": {"type": "box", "half_size": [1, 1, 1]}},
        {"shape": {"type": "isosurface", "function": "length(p) - 0.5", "contained_by": {"sphere": {"radius": 1}}}}]})"));
    const auto hits = hit_sequence(*scene, make_ray({-3, 0.1, 0.05}, {1, 0, 0}));
    ASSERT_EQ(hits.size(), 4u);
    const double inner = std::sqrt(0.25 - 0.01 - 0.0025);
    EXPECT_NEAR(hits[1].t, 3 - inner, 1e-5);
    EXPECT_NEAR(hits[2].t, 3 + inner, 1e-5);

    const auto shape = shape_from_json(
        R"({"type": "isosurface", "function": "length(p) - 0.5", "contained_by": {"box": {"min": [-1, -1, 0], "max": [1, 1, 1]}}})");
    const auto field = shape->implicit_field();
    EXPECT_LT(field->value({0, 0, 0.25}), 0);
    EXPECT_GT(field->value({0, 0, -0.25}), 0);  // the container cuts the ball in half
    EXPECT_NEAR(*shape->field_value({0, 0, 0.25}), 0.25, 1e-12);
}

// Without contained_by, a bounded function gets a derived container and is traced as with one.
TEST(IsosurfacePlugin, ABoundedFunctionNeedsNoContainer) {
    const auto shape = shape_from_json(R"({"type": "isosurface", "function": "length(p - vec(3, 0, 0)) - 1"})");
    const auto hit = first_hit(*shape, {3, 0, -5}, {0, 0, 1});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4, 1e-12);
    EXPECT_NEAR(hit->normal.z, -1, 1e-12);
    EXPECT_FALSE(first_hit(*shape, {0, 0, -5}, {0, 0, 1}));
}

TEST(IsosurfacePlugin, BadInputIsRefusedAtItsPlace) {
    EXPECT_NE(error_of(R"({"type": "isosurface", "function": "z"})").find("contained_by"), std::string::npos);
    EXPECT_NE(error_of(R"({"type": "isosurface", "function": "length(p) + 1"})").find("no surface"), std::string::npos);
    EXPECT_NE(error_of(R"({"type": "isosurface", "function": "length(p) - 1",
                           "contained_by": {"sphere": {"radius": 0}}})").find("contained_by.sphere.radius"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"type": "isosurface", "function": "length(p) - 1",
                           "contained_by": {"box": {"min": [0, 0, 0], "max": [1, 0, 1]}}})").find("hold nothing"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"type": "isosurface", "function": "length(p) - 1",
                           "contained_by": {"cube": {}}})").find("cube"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"type": "isosurface", "function": "length(p) - 1",
                           "contained_by": {"box": {"min": [5, 5, 5], "max": [6, 6, 6]}}})").find("no surface"),
              std::string::npos);
    EXPECT_NE(error_of(R"json({"type": "isosurface", "function": "length(p) - sqrt(-1)",
                           "contained_by": {"sphere": {"radius": 2}}})json").find("function"),
              std::string::npos);
    EXPECT_NE(error_of(R"json({"type": "isosurface", "function": "b(p)", "fields": {"b": {"type": "mesh", "file": "x.obj"}},
                           "contained_by": {"sphere": {"radius": 2}}})json").find("fields.b"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"type": "isosurface", "function": "length(p) - 1", "max_work": 1,
                           "contained_by": {"sphere": {"radius": 2}}})").find("max_work"),
              std::string::npos);
}

}  // namespace
}  // namespace isotrace
