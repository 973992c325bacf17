// The scene option "tessellate": an implicit object traced as its polygonisation, and the errors for bad settings
// (reported at the JSON path of the setting).
#include <gtest/gtest.h>

#include <string>

#include "geometry/mesh/mesh_test_support.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace {
namespace {

using mesh_test::input_error_message;
using mesh_test::ScratchDirectory;

std::string scene_with_object(const std::string& object_fields) {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"plain": {"type": "diffuse"}},
  "objects": [{"material": "plain", )" +
           object_fields + "}]}";
}

// A ball of radius 1 about (0.5, 0, 0) placed 1 further along x: the mesh is baked like any mesh, so a camera ray
// along −z through x = 1.5 meets the top of the sphere, at z ≈ 1 (the tessellation's chordal error apart).
TEST(TessellatedShape, AnImplicitObjectIsTracedAsItsMesh) {
    ScratchDirectory dir;
    for (const char* method : {R"("mc")", R"("dc")", R"("sdc")", R"("dc", "simplify": 0.001)"}) {
        const auto loaded = load_scene(dir.write(
            "ball.json", scene_with_object(R"("transform": {"translate": [1, 0, 0]},
              "shape": {"type": "sphere", "center": [0.5, 0, 0], "radius": 1},
              "tessellate": {"method": )" + std::string(method) + R"(, "depth": 5})")));
        const SceneObject& object = loaded->scene->objects().at(0);
        EXPECT_EQ(object.shape->type_name(), "triangle_mesh") << method;
        Ray ray;
        ray.origin = {1.5f, 0.0f, 5.0f};
        ray.direction = {0.0f, 0.0f, -1.0f};
        const auto hit = loaded->scene->intersect(ray, RayKind::Camera);
        ASSERT_TRUE(hit) << method;
        EXPECT_NEAR(hit->t, 4.0, 0.02) << method;
    }
}

TEST(TessellatedShape, BadSettingsAreReportedWhereTheyAreWritten) {
    ScratchDirectory dir;
    const auto error_for = [&](const std::string& object_fields) {
        return input_error_message([&] { load_scene(dir.write("bad.json", scene_with_object(object_fields))); });
    };
    EXPECT_NE(error_for(R"("shape": {"type": "sphere"}, "tessellate": {"depth": 11})").find("objects[0].tessellate.depth"),
              std::string::npos);
    EXPECT_NE(error_for(R"("shape": {"type": "sphere"}, "tessellate": {"method": "mt"})").find("objects[0].tessellate.method"),
              std::string::npos);
    EXPECT_NE(error_for(R"("shape": {"type": "sphere"}, "tessellate": {"simplify": -1})").find("objects[0].tessellate.simplify"),
              std::string::npos);
    const std::string simplify_mc = error_for(R"("shape": {"type": "sphere"}, "tessellate": {"method": "mc", "simplify": 0.01})");
    EXPECT_NE(simplify_mc.find("only dual contouring"), std::string::npos) << simplify_mc;
    const std::string origin = error_for(R"("shape": {"type": "sphere"}, "tessellate": {"method": "sdc", "origin": [5, 0, 0]})");
    EXPECT_NE(origin.find("origin"), std::string::npos) << origin;
    for (const char* setting : {R"("origin": [0, 0, 0])", R"("pole_cap": "normal")"}) {
        const std::string for_dc = error_for(std::string(R"("shape": {"type": "sphere"}, "tessellate": {"method": "dc", )") +
                                             setting + "}");
        EXPECT_NE(for_dc.find("applies only to spherical-octree dual contouring"), std::string::npos) << for_dc;
    }
    const std::string open_mesh = error_for(R"("shape": {"type": "mesh", "positions": [[0,0,0], [1,0,0], [0,1,0]], "triangles": [[0,1,2]]},
        "tessellate": {})");
    EXPECT_NE(open_mesh.find("boundary edges"), std::string::npos) << open_mesh;
}

}  // namespace
}  // namespace isotrace
