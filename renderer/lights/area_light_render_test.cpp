// A rectangle light rendered with the path tracer: the same picture, within noise, as the same square emitter made
// of two triangles (sampled by area), with less noise, because the rectangle is sampled by solid angle and the
// multiple-importance weights use the density it was drawn with.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

// A diffuse floor 40 cm below a 1 m square emitter facing down, seen from the side below the emitter; `light` is
// the emitter's shape.
std::string scene_with_light(const std::string& light) {
    return R"({"isotrace": 1, "film": {"resolution": [24, 24], "spp": 16},
  "camera": {"type": "perspective", "fov": 60, "look_at": {"eye": [0, 0.3, 1.8], "target": [0, 0.05, 0]}},
  "integrator": {"type": "path", "max_depth": 2},
  "materials": {"floor": {"type": "diffuse", "reflectance": 0.7}, "lamp": {"type": "emissive", "radiance": 4}},
  "objects": [
    {"name": "floor", "material": "floor", "shape": {"type": "mesh", "positions": [[-3, 0, -3], [-3, 0, 3], [3, 0, 3], [3, 0, -3]], "triangles": [[0, 1, 2], [0, 2, 3]]}},
    {"name": "lamp", "material": "lamp", "shape": )" + light + R"(}]})";
}

struct FloorEstimate {
    double mean = 0;             // the red channel averaged over the pixels
    double variance_of_mean = 0; // of that average
    double mean_pixel_variance = 0;
};

FloorEstimate render(const std::string& light) {
    const testing::SceneFile file(scene_with_light(light));
    const auto scene = load_scene(file.path());
    RenderOptions options;
    options.spp = 16;
    const RenderResult result = render_scene(*scene, options);
    FloorEstimate e;
    int pixels = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            const PixelStatistics p = result.film->pixel_statistics(x, y);
            e.mean += p.mean[0];
            e.variance_of_mean += p.variance_of_mean[0];
            ++pixels;
        }
    e.mean /= pixels;
    e.mean_pixel_variance = e.variance_of_mean / pixels;
    e.variance_of_mean /= double(pixels) * pixels;
    return e;
}

TEST(AreaLightRender, RectangleLightMatchesTheTriangleSquareWithLessNoise) {
    // The rectangle and the two triangles cover the same square at y = 0.4, both facing down.
    const FloorEstimate rectangle = render(R"({"type": "rectangle", "center": [0, 0.4, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1]})");
    const FloorEstimate triangles = render(
        R"({"type": "mesh", "positions": [[-0.5, 0.4, -0.5], [0.5, 0.4, -0.5], [0.5, 0.4, 0.5], [-0.5, 0.4, 0.5]], "triangles": [[0, 1, 2], [0, 2, 3]]})");
    ASSERT_GT(rectangle.mean, 0.05);
    EXPECT_NEAR(rectangle.mean, triangles.mean, 4 * std::sqrt(rectangle.variance_of_mean + triangles.variance_of_mean))
        << rectangle.mean << " vs " << triangles.mean;
    EXPECT_LT(rectangle.mean_pixel_variance, 0.85 * triangles.mean_pixel_variance)  // 0.75 at this seed
        << rectangle.mean_pixel_variance << " vs " << triangles.mean_pixel_variance;
}

}  // namespace
}  // namespace isotrace
