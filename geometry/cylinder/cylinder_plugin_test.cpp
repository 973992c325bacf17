// The "cylinder" plugin: what it builds from a scene (a frustum with equal radii, named "cylinder"), that it traces
// and forms solids as the frustum does, and its scene-format errors at their keys.
#include <gtest/gtest.h>

#include <string>

#include "geometry/cone/frustum_shape.h"
#include "geometry/cone/round_shapes_test_support.h"
#include "geometry/csg/csg_test_support.h"
#include "geometry/mesh/mesh_test_support.h"
#include "renderer/scene/loaded_scene.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {
namespace {

using round_test::scene_with_shape;

TEST(CylinderScene, LoadsAFrustumOfEqualRadii) {
    mesh_test::ScratchDirectory dir;
    const auto loaded = load_scene(dir.write(
        "c.json", scene_with_shape(R"({"type": "cylinder", "base": [1, 0, 0], "top": [1, 0, 4], "radius": 0.5})")));
    const Shape& shape = *loaded->scene->objects()[0].shape;
    EXPECT_EQ(shape.type_name(), "cylinder");
    const Frustum& f = static_cast<const FrustumShape&>(shape).frustum();
    EXPECT_EQ(f.origin, Vec3d(1, 0, 0));
    EXPECT_EQ(f.axis, Vec3d(0, 0, 1));
    EXPECT_EQ(f.height, 4);
    EXPECT_EQ(f.base_radius, 0.5);
    EXPECT_EQ(f.top_radius, 0.5);
    EXPECT_TRUE(f.caps);
    const auto hit = loaded->scene->intersect(csg_test::make_ray({1, -3, 2}, {0, 1, 0}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2.5f);
    // Defaults: radius 1 from the origin to (0, 1, 0), capped; "caps": false opens it.
    const auto open = load_scene(dir.write("o.json", scene_with_shape(R"({"type": "cylinder", "caps": false})")));
    const Frustum& g = static_cast<const FrustumShape&>(*open->scene->objects()[0].shape).frustum();
    EXPECT_EQ(g.axis, Vec3d(0, 1, 0));
    EXPECT_EQ(g.height, 1);
    EXPECT_EQ(g.base_radius, 1);
    EXPECT_FALSE(g.caps);
}

TEST(CylinderScene, ACappedCylinderIsACsgSolid) {
    mesh_test::ScratchDirectory dir;
    // A unit box with a hole of radius 0.5 along y: a ray down the hole passes, one beside it hits the top.
    const auto loaded = load_scene(dir.write("c.json", scene_with_shape(R"({"type": "csg", "op": "difference", "children": [
        {"shape": {"type": "box"}}, {"shape": {"type": "cylinder", "base": [0, -2, 0], "top": [0, 2, 0], "radius": 0.5}}]})")));
    EXPECT_FALSE(loaded->scene->intersect(csg_test::make_ray({0.2, 5, 0}, {0, -1, 0}), RayKind::Camera));
    const auto hit = loaded->scene->intersect(csg_test::make_ray({0.7, 5, 0}, {0, -1, 0}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4.0f);
    // Across the hole: the wall of the hole, normal towards the axis (out of the difference).
    const auto wall = loaded->scene->intersect(csg_test::make_ray({0, 0, 0}, {1, 0, 0}), RayKind::Camera);
    ASSERT_TRUE(wall);
    EXPECT_FLOAT_EQ(wall->t, 0.5f);
    EXPECT_NEAR(wall->geometric_normal.x, -1.0f, 1e-6f);
}

TEST(CylinderScene, BadInputIsAnInputErrorAtTheKey) {
    const round_test::BadInput cases[] = {
        {R"({"type": "cylinder", "radius": 0})", "objects[0].shape.radius"},
        {R"({"type": "cylinder", "radius": -2})", "objects[0].shape.radius"},
        {R"({"type": "cylinder", "top": [0, 0, 0]})", "objects[0].shape.top"},
        {R"({"type": "cylinder", "base": [5, 5, 5], "top": [5, 5, 5]})", "objects[0].shape.top"},
        {R"({"type": "cylinder", "top": [0, 1]})", "objects[0].shape.top"},
        {R"({"type": "cylinder", "base": [0, 0, 0], "top": [0, 2e18, 0]})", "objects[0].shape"},
        {R"({"type": "cylinder", "caps": "yes"})", "objects[0].shape.caps"},
        {R"({"type": "cylinder", "radius": 1, "axis": [0, 1, 0]})", "axis"},
        {R"({"type": "cylinder", "radius": NaN})", "expected a JSON value"},  // JSON has no NaN
    };
    round_test::expect_input_errors(cases);
}

TEST(CylinderScene, AnOpenCylinderIsRejectedAsACsgChildAtTheChild) {
    mesh_test::ScratchDirectory dir;
    const std::string path = dir.write("c.json", scene_with_shape(R"({"type": "csg", "op": "union", "children": [
        {"shape": {"type": "box"}}, {"shape": {"type": "cylinder", "caps": false}}]})"));
    const std::string message = mesh_test::input_error_message([&] { load_scene(path); });
    EXPECT_NE(message.find("open cylinder"), std::string::npos) << message;
    EXPECT_NE(message.find("objects[0].shape.children[1]"), std::string::npos) << message;
}

}  // namespace
}  // namespace isotrace
