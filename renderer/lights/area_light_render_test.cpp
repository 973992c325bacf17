// A rectangle light rendered with the path tracer: the same picture, within noise, as the same square emitter made
// of two triangles (sampled by area), with less noise, because the rectangle is sampled by solid angle and the
// multiple-importance weights use the density it was drawn with.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "renderer/math/vec3.h"
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

// Irradiance at `point` on a surface with unit normal `normal` from a convex polygon of uniform radiance `radiance`
// (Lambert's formula: half the radiance times the sum, over the edges, of the angle each subtends times the cosine
// between `normal` and the normal of the plane through `point` and that edge).
double polygon_irradiance(const std::array<Vec3d, 4>& corners, const Vec3d& point, const Vec3d& normal, double radiance) {
    double sum = 0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const Vec3d a = normalize(corners[i] - point), b = normalize(corners[(i + 1) % corners.size()] - point);
        sum += std::acos(std::clamp(dot(a, b), -1.0, 1.0)) * dot(normalize(cross(a, b)), normal);
    }
    return 0.5 * radiance * std::abs(sum);
}

// A 1 m square lamp facing down, low over a white floor, seen straight down from above a floor point 30 cm beyond
// its edge: every shadow ray meets the lamp's plane at a grazing angle. Pushing the shadow ray's origin off the
// floor without aiming it again at the lamp's point shortened its way to that plane by more than the ray's margin,
// and the lamp's own surface shadowed the floor (black at 13 cm). Each integrator that samples the lamp must see
// the floor's analytic radiance, reflectance / pi times the irradiance.
TEST(AreaLightRender, LampLowOverTheFloorLightsItAsTheAnalyticIrradianceSays) {
    for (const std::string integrator : {R"({"type": "preview", "ambient": 0})", R"({"type": "path", "max_depth": 1})"})
        for (const double height : {0.3, 0.13, 0.05, 0.02}) {
            const std::string y = std::to_string(height);
            const testing::SceneFile file(R"({"isotrace": 1, "film": {"resolution": [8, 8], "spp": 64},
  "camera": {"type": "perspective", "fov": 0.5, "look_at": {"eye": [0.8, 1, 0], "target": [0.8, 0, 0], "up": [0, 0, -1]}},
  "integrator": )" + integrator + R"(,
  "materials": {"white": {"type": "diffuse", "reflectance": 1}, "lamp": {"type": "emissive", "radiance": 4}},
  "objects": [
    {"name": "floor", "material": "white", "shape": {"type": "mesh", "positions": [[-5, 0, -5], [5, 0, -5], [5, 0, 5], [-5, 0, 5]], "triangles": [[0, 2, 1], [0, 3, 2]]}},
    {"name": "lamp", "material": "lamp", "shape": {"type": "mesh", "positions": [[-0.5, )" + y + R"(, -0.5], [0.5, )" + y +
                                          R"(, -0.5], [0.5, )" + y + R"(, 0.5], [-0.5, )" + y +
                                          R"(, 0.5]], "triangles": [[0, 1, 2], [0, 2, 3]]}}]})");
            const auto scene = load_scene(file.path());
            RenderOptions options;
            options.spp = 64;
            const RenderResult result = render_scene(*scene, options);
            double mean = 0, variance_of_mean = 0;
            for (int py = 0; py < 8; ++py)
                for (int px = 0; px < 8; ++px) {
                    const PixelStatistics p = result.film->pixel_statistics(px, py);
                    mean += p.mean[0] / 64;
                    variance_of_mean += p.variance_of_mean[0] / (64.0 * 64.0);
                }
            const std::array<Vec3d, 4> lamp = {Vec3d(-0.5, height, -0.5), Vec3d(0.5, height, -0.5),
                                               Vec3d(0.5, height, 0.5), Vec3d(-0.5, height, 0.5)};
            const double expected =
                polygon_irradiance(lamp, {0.8, 0, 0}, {0, 1, 0}, 4) * std::numbers::inv_pi;
            // The pixels see the floor within 4.4 mm of the point: the irradiance varies by well under 1 % there.
            EXPECT_NEAR(mean, expected, 4 * std::sqrt(variance_of_mean) + 0.01 * expected)
                << integrator << " at height " << height;
        }
}

}  // namespace
}  // namespace isotrace
