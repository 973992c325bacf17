// The "abm_patch" shape in a scene: named shared curves, a hit on the tessellated surface, errors at their place.
#include <gtest/gtest.h>

#include "geometry/csg/csg_test_support.h"
#include "geometry/mesh/mesh_test_support.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace {
namespace {

std::string scene_with(const std::string& shape) {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"material": "m", "shape": )" + shape + "}]}";
}

// The planar unit square as two triangles' worth of patches: a three-sided one on the left half-diagonal and
// a three-sided one on the right, sharing the diagonal "d" (each in its own direction).
const char* kTwoPatches = R"({"type": "abm_patch", "tolerance": 1e-3,
  "curves": {"d": {"points": [[0, 0, 0], [1, 1, 0]]}},
  "patches": [
    {"boundary": ["d", {"points": [[1, 1, 0], [0, 1, 0]]}, {"points": [[0, 1, 0], [0, 0, 0]]}]},
    {"boundary": [{"curve": "d", "reversed": true}, {"points": [[0, 0, 0], [1, 0, 0]]}, {"type": "bspline", "degree": 2, "points": [[1, 0, 0], [1, 0.5, 0], [1, 1, 0]]}]}]})";

TEST(AbmPatchScene, TwoPatchesSharingACurveAreHit) {
    mesh_test::ScratchDirectory dir;
    const auto loaded = load_scene(dir.write("patches.json", scene_with(kTwoPatches)));
    for (const Vec3d& target : {Vec3d{0.25, 0.6, 0}, Vec3d{0.7, 0.2, 0}, Vec3d{0.5, 0.5, 0}}) {
        const auto hit = loaded->scene->intersect(csg_test::make_ray(target + Vec3d{0, 0, 3}, {0, 0, -1}), RayKind::Camera);
        ASSERT_TRUE(hit) << target.x << " " << target.y;
        EXPECT_NEAR(hit->t, 3, 1e-5);
    }
}

TEST(AbmPatchScene, ErrorsNameTheirPlace) {
    mesh_test::ScratchDirectory dir;
    struct Case {
        std::string shape, where, text;
    };
    const Case cases[] = {
        {R"({"type": "abm_patch", "p": 0, "boundary": [{"points": [[0,0,0],[1,0,0]]}, {"points": [[1,0,0],[0,1,0]]}, {"points": [[0,1,0],[0,0,0]]}]})",
         "objects[0].shape.p", "out of range"},
        {R"({"type": "abm_patch", "boundary": [{"points": [[0,0,0],[1,0,0]]}, {"points": [[1,0,0],[0,1,0]]}, {"points": [[0,1,0],[0,0,1]]}]})",
         "objects[0].shape.boundary", "curve 2 ends at (0, 0, 1) but curve 0 starts at (0, 0, 0), a gap of 1"},
        {R"({"type": "abm_patch", "boundary": [{"points": [[0,0,0],[1,0,0]]}, {"points": [[1,0,0],[0,1,0]]}]})",
         "objects[0].shape.boundary", "3 to 8 boundary curves, got 2"},
        {R"({"type": "abm_patch", "boundary": ["a", "b", "c"]})", "objects[0].shape.boundary[0]", "no curve named \"a\""},
        {R"({"type": "abm_patch", "domain": "square", "boundary": [{"points": [[0,0,0],[1,0,0]]}, {"points": [[1,0,0],[0,1,0]]}, {"points": [[0,1,0],[0,0,0]]}]})",
         "objects[0].shape.domain", "needs 4 curves"},
    };
    for (const Case& c : cases) {
        const std::string path = dir.write("bad.json", scene_with(c.shape));
        const std::string message = mesh_test::input_error_message([&] { load_scene(path); });
        EXPECT_NE(message.find(path + ":"), std::string::npos) << message;
        EXPECT_NE(message.find(c.where + ": "), std::string::npos) << message;
        EXPECT_NE(message.find(c.text), std::string::npos) << message;
    }
}

// Patches of 1e100 took minutes in the normals of their overflowing vertices; far-out points are refused at
// their place, like the 1e18 limit of the other shapes.
TEST(AbmPatchScene, ControlPointsBeyond1e18AreRefusedWhereTheyStand) {
    mesh_test::ScratchDirectory dir;
    const std::string path = dir.write("far.json", scene_with(
        R"({"type": "abm_patch", "boundary": [{"points": [[0,0,0],[1e100,0,0]]}, {"points": [[1e100,0,0],[0,1e100,0]]}, {"points": [[0,1e100,0],[0,0,0]]}]})"));
    const std::string message = mesh_test::input_error_message([&] { load_scene(path); });
    EXPECT_NE(message.find("objects[0].shape.boundary[0].points[1]: control point lies beyond 1e18 from the origin"),
              std::string::npos)
        << message;
}

}  // namespace
}  // namespace isotrace
