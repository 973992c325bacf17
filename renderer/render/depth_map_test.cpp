// render_depth_map(): the view depth (world units, along the viewing axis) of the first hit per pixel centre.
#include "renderer/render/depth_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include <string>

#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

using testing::SceneFile;

// A 3 x 4 m quad in the plane z = 0 seen by a perspective camera placed by `placement` (a "look_at" or a
// "transform" member).
std::string plane_scene(const std::string& placement) {
    return R"({"isotrace": 1,
  "film": {"resolution": [24, 16], "spp": 1},
  "camera": {"type": "perspective", "fov": 60, )" + placement + R"(},
  "materials": {"m": {"type": "diffuse"}},
  "objects": [
    {"material": "m", "shape": {"type": "mesh", "positions": [[-2, -2, 0], [1, -2, 0], [1, 2, 0], [-2, 2, 0]],
     "triangles": [[0, 1, 2], [0, 2, 3]]}}]})";
}

// Facing the plane squarely from 4 m, every pixel that hits it (centre or not) is at depth 4, not at the
// longer distance along its oblique ray.
TEST(DepthMap, PlaneFacingTheCameraIsAtItsDistanceInEveryPixel) {
    const SceneFile file(plane_scene(R"("look_at": {"eye": [0.5, 0.25, 4], "target": [0.5, 0.25, 0]})"));
    const auto scene = load_scene(file.path());
    const DepthMap map = render_depth_map(*scene);
    ASSERT_EQ(map.depth.size(), 24u * 16u);
    int hits = 0, misses = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) {
            if (std::isinf(map.at(x, y))) {
                ++misses;
                continue;
            }
            ++hits;
            EXPECT_NEAR(map.at(x, y), 4.0f, 1e-5f) << x << ", " << y;
        }
    EXPECT_GT(hits, 200);
    EXPECT_GT(misses, 10);  // right of x = 1 the quad ends
    EXPECT_NEAR(map.at(0, 0), 4.0f, 1e-5f);  // a corner pixel, the most oblique ray
}

// A placement transform that scales (here by 2) must not change the depth: it is in world units.
TEST(DepthMap, ScaledCameraTransformStillGivesWorldUnits) {
    const SceneFile file(plane_scene(R"("transform": {"translate": [-0.5, 0, 4], "scale": 2})"));
    const auto scene = load_scene(file.path());
    const DepthMap map = render_depth_map(*scene);
    int hits = 0;
    for (float depth : map.depth)
        if (!std::isinf(depth)) {
            EXPECT_NEAR(depth, 4.0f, 1e-5f);
            ++hits;
        }
    EXPECT_GT(hits, 200);
}

// Seen obliquely, the depth is (P − eye)·forward for the hit point P on the plane z = 0.
TEST(DepthMap, ObliquePlaneDepthIsTheDistanceAlongTheViewingAxis) {
    const Vec3d eye(0.3, -1.0, 3.0), target(-0.2, 0.4, 0.0);
    const SceneFile file(plane_scene(R"("look_at": {"eye": [0.3, -1.0, 3.0], "target": [-0.2, 0.4, 0.0]})"));
    const auto scene = load_scene(file.path());
    const DepthMap map = render_depth_map(*scene);
    const Vec3d forward = normalize(target - eye);
    int checked = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) {
            const Ray ray = scene->camera->generate_ray(float(x) + 0.5f, float(y) + 0.5f, {0.5f, 0.5f});
            const Vec3d o(ray.origin), d(ray.direction);
            const Vec3d hit = o + d * (-o.z / d.z);
            if (hit.x < -2 || hit.x > 1 || hit.y < -2 || hit.y > 2) continue;
            EXPECT_NEAR(map.at(x, y), dot(hit - eye, forward), 1e-5 * length(hit - eye)) << x << ", " << y;
            ++checked;
        }
    EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace isotrace
