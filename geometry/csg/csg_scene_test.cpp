// The "csg" scene type: per-child materials through the loader, nesting and child transforms from JSON, and
// the input errors (with file:line:column and JSON path) for bad operators, children and materials.
#include <gtest/gtest.h>

#include <string>

#include "geometry/csg/csg_test_support.h"
#include "geometry/mesh/mesh_test_support.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace {
namespace {

using csg_test::make_ray;
using mesh_test::input_error_message;
using mesh_test::ScratchDirectory;

// A shape that is a surface but not a solid, registered for these tests only.
class SurfaceOnlyShape final : public Shape {
public:
    std::string type_name() const override { return "test_surface_only"; }
    std::size_t primitive_count() const override { return 0; }
    Bounds3f bounds() const override { return {}; }
    bool can_bake(const Transform&) const override { return true; }
    void bake(const Transform&) override {}
    RTCGeometry create_geometry(RTCDevice device) override { return rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER); }
};

ISOTRACE_REGISTER_PLUGIN(shape_registry, "test_surface_only", "a surface that is not a solid (CSG tests)",
                         [](const SceneNode&) -> std::unique_ptr<Shape> { return std::make_unique<SurfaceOnlyShape>(); })

std::string scene_with_shape(const std::string& shape) {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"plain": {"type": "diffuse"}, "red": {"type": "diffuse", "reflectance": [0.8, 0.1, 0.1]},
                "blue": {"type": "diffuse", "reflectance": [0.1, 0.1, 0.8]}},
  "objects": [{"material": "plain", "shape": )" +
           shape + "}]}";
}

// The nearest hit of `ray`, which must lie at `t` and show the material called `material`.
SurfaceHit expect_hit(const RenderScene& scene, const Ray& ray, double t, const std::string& material,
                      const std::string& what) {
    const auto hit = scene.intersect(ray, RayKind::Camera);
    if (!hit) {
        ADD_FAILURE() << what << ": no hit";
        return {};
    }
    EXPECT_NEAR(hit->t, t, 1e-5) << what;
    EXPECT_EQ(hit->material, scene.find_material(material)) << what;
    return *hit;
}

// A red box with a blue spherical bite out of its +z face, and a child without a material of its own.
constexpr const char* kBittenBox = R"({"type": "csg", "op": "difference", "children": [
    {"shape": {"type": "box", "half_size": [1, 1, 1]}, "material": "red"},
    {"shape": {"type": "sphere", "center": [0, 0, 1], "radius": 0.5}, "material": "blue"},
    {"shape": {"type": "box", "center": [0, 0, -1], "half_size": [0.25, 0.25, 0.25]}}]})";

TEST(CsgScene, HitsReportTheMaterialOfTheChildThatBoundsTheResult) {
    ScratchDirectory dir;
    const auto loaded = load_scene(dir.write("bitten.json", scene_with_shape(kBittenBox)));
    const RenderScene& scene = *loaded->scene;
    expect_hit(scene, make_ray({0.75, 0, 5}, {0, 0, -1}), 4, "red", "the box's top");
    const auto in_bite = expect_hit(scene, make_ray({0, 0, 5}, {0, 0, -1}), 4.5, "blue", "the bite");
    csg_test::expect_near(in_bite.geometric_normal, {0, 0, 1}, 1e-6, "floor of the bite faces out of the box");
    expect_hit(scene, make_ray({0, 0, -5}, {0, 0, 1}), 4.25, "plain", "no child material: the object's");
}

TEST(CsgScene, NestedTreesInheritTheirMaterialAndChildTransformsApply) {
    ScratchDirectory dir;
    const std::string shape = R"({"type": "csg", "op": "union", "children": [
      {"shape": {"type": "csg", "op": "intersection", "children": [
          {"shape": {"type": "sphere", "radius": 1}},
          {"shape": {"type": "box", "half_size": [2, 2, 0.5]}, "material": "blue"}]},
       "material": "red", "transform": {"translate": [0, 0, 3]}},
      {"shape": {"type": "sphere", "radius": 1}, "transform": {"scale": [2, 1, 1]}}]})";
    const auto loaded = load_scene(dir.write("nested.json", scene_with_shape(shape)));
    const RenderScene& scene = *loaded->scene;
    // Down the z axis: the lens (sphere ∩ slab) at z = 3 ± 0.5, its top is the slab's face (blue).
    expect_hit(scene, make_ray({0, 0, 10}, {0, 0, -1}), 6.5, "blue", "the slab's face");
    // Its rim is the sphere's surface, which inherits red from the nested CSG's child entry.
    expect_hit(scene, make_ray({10, 0, 3}, {-1, 0, 0}), 9, "red", "the lens's rim");
    // The ellipsoid (scaled sphere, kept under its transform) reaches x = 2 at z = 0.
    expect_hit(scene, make_ray({10, 0, 0}, {-1, 0, 0}), 8, "plain", "the ellipsoid");
}

struct BadInput {
    std::string shape;
    std::string path;     // the JSON path the message must name
    std::string problem;  // and a piece of the problem
};

TEST(CsgScene, BadInputIsAnInputErrorAtItsPlace) {
    ScratchDirectory dir;
    const std::string open_box = R"({"type": "mesh", "positions": [[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1]],
        "triangles": [[0,2,3],[0,3,1],[4,5,7],[4,7,6],[0,1,5],[0,5,4],[2,6,7],[2,7,3],[0,4,6],[0,6,2]]})";
    const BadInput cases[] = {
        {R"({"type": "csg", "op": "union", "children": []})", "objects[0].shape.children", "at least one child"},
        {R"({"type": "csg", "op": "union"})", "objects[0].shape", "children"},
        {R"({"type": "csg", "children": [{"shape": {"type": "sphere"}}]})", "objects[0].shape", "\"op\""},
        {R"({"type": "csg", "op": "unoin", "children": [{"shape": {"type": "sphere"}}]})", "objects[0].shape.op",
         "did you mean \"union\""},
        {R"({"type": "csg", "op": "union", "children": [{"shape": {"type": "sphere"}}, {"shape": )" + open_box + "}]}",
         "objects[0].shape.children[1]", "CSG needs a closed solid; triangle_mesh has 4 boundary edges (e.g. 1–3)"},
        {R"({"type": "csg", "op": "union", "children": [{"shape": {"type": "test_surface_only"}}]})",
         "objects[0].shape.children[0]", "CSG needs a closed solid; test_surface_only is not a solid"},
        {R"({"type": "csg", "op": "union", "children": [{"shape": {"type": "sphere"}, "material": "bleu"}]})",
         "objects[0].shape.children[0].material", "unknown material \"bleu\""},
        {R"({"type": "csg", "op": "union", "children": [{"shape": {"type": "sphere"}, "material": 3}]})",
         "objects[0].shape.children[0].material", "expected the name of a material"},
        {R"({"type": "csg", "op": "union", "children": [{"shape": {"type": "sphere"}, "colour": 3}]})",
         "objects[0].shape.children[0].colour", "unknown key \"colour\""},
    };
    for (const BadInput& c : cases) {
        const std::string path = dir.write("bad.json", scene_with_shape(c.shape));
        const std::string message = input_error_message([&] { load_scene(path); });
        EXPECT_NE(message.find(path + ":"), std::string::npos) << message;
        EXPECT_NE(message.find(c.path + ":"), std::string::npos) << message;
        EXPECT_NE(message.find(c.problem), std::string::npos) << message;
    }
}

TEST(CsgScene, UnknownChildMaterialIsReportedWhereItIsWritten) {
    ScratchDirectory dir;
    const std::string path = dir.write("where.json", scene_with_shape(R"({"type": "csg", "op": "union",
      "children": [{"shape": {"type": "sphere"}},
                   {"shape": {"type": "box"}, "material": "bleu"}]})"));
    const std::string message = input_error_message([&] { load_scene(path); });
    EXPECT_NE(message.find(path + ":7:"), std::string::npos) << message;
    EXPECT_NE(message.find("did you mean \"blue\""), std::string::npos) << message;
}

}  // namespace
}  // namespace isotrace
