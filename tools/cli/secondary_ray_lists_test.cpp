// build_secondary_rays: the benchmark's light is placed from the objects' own bounds, so that a change to how a shape
// bounds itself for Embree (a blob group's cell boxes) does not move it and change every shadow ray.
#include "tools/cli/secondary_ray_lists.h"

#include <gtest/gtest.h>

#include "renderer/scene/loaded_scene.h"
#include "tests/support/scene_files.h"

namespace isotrace::cli {
namespace {

// One Kim metaball of radius 2 at the origin, threshold 0.5: its surface is a sphere of radius ~1.08, well inside its
// support [-2, 2]³, and Embree's bounds are its cells' boxes shrunk to where the surface may be.
TEST(SecondaryRayLists, LightIsPlacedFromTheShapesOwnBoundsNotEmbrees) {
    const testing::SceneFile file(R"({"isotrace": 1,
  "film": {"resolution": [16, 16], "spp": 1},
  "camera": {"type": "perspective", "fov": 40, "look_at": {"eye": [0, 0, 10], "target": [0, 0, 0]}},
  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"material": "m", "shape": {"type": "blobs", "field": "kim", "threshold": 0.5,
    "elements": [{"center": [0, 0, 0], "half_size": 0, "radius": 2, "weight": 1}]}}]})");
    const auto scene = load_scene(file.path());
    ASSERT_LT(scene->scene->bounds().upper.y, 1.9f);  // Embree's: the surface's cells, not the support
    const SecondaryRayLists lists = build_secondary_rays(*scene);
    // The support's top face (y = 2), raised by its height (4).
    EXPECT_NEAR(lists.light.x, 0.0f, 1e-6f);
    EXPECT_NEAR(lists.light.y, 6.0f, 1e-5f);
    EXPECT_NEAR(lists.light.z, 0.0f, 1e-6f);
    EXPECT_GT(lists.primary_hits, 0u);
    EXPECT_FALSE(lists.shadow.empty());
}

// Every secondary ray starts off the surface by at least the clearance, on the side it travels to: a unit sphere
// seen from outside, so every origin lies at least 1 + clearance from its centre.
TEST(SecondaryRayLists, OriginsKeepTheClearanceFromTheSurface) {
    const testing::SceneFile file(R"({"isotrace": 1,
  "film": {"resolution": [16, 16], "spp": 1},
  "camera": {"type": "perspective", "fov": 30, "look_at": {"eye": [0, 0, 6], "target": [0, 0, 0]}},
  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"material": "m", "shape": {"type": "sphere", "radius": 1}}]})");
    const auto scene = load_scene(file.path());
    constexpr float kClearance = 0.05f;
    const SecondaryRayLists lists = build_secondary_rays(*scene, kClearance);
    ASSERT_FALSE(lists.shadow.empty());
    ASSERT_FALSE(lists.bounce.empty());
    for (const std::vector<Ray>* rays : {&lists.shadow, &lists.bounce})
        for (const Ray& ray : *rays) EXPECT_GE(length(ray.origin), 1 + 0.99f * kClearance);
    // Without a clearance they start within the position error of the surface.
    for (const Ray& ray : build_secondary_rays(*scene).bounce) EXPECT_LT(length(ray.origin), 1 + 1e-3f);
}

}  // namespace
}  // namespace isotrace::cli
