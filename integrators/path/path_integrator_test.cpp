// Known answers for the path tracer: white furnaces, a glowing sphere seen from inside, direct lighting from a
// small area light against the closed-form irradiance, and the 1/spp fall of the squared error; and a pixel's
// samples traced in step giving each sample's own bits.
#include "integrators/path/path_integrator.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "renderer/core/render_counters.h"
#include "renderer/render/tile_renderer.h"
#include "renderer/sampling/sampler.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/samples_together.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

using testing::TemporaryDirectory;

// Renders `scene_text` and returns the beauty RGB (3 floats per pixel) and alpha.
struct Rendered {
    std::vector<float> rgb;
    std::vector<float> alpha;
};

Rendered render_text(const std::string& scene_text, int spp, std::uint64_t seed = 0) {
    TemporaryDirectory directory("path_integrator");
    const auto path = directory.write("scene.json", scene_text);
    SceneOverrides overrides;
    overrides.settings.push_back(spp_setting(spp));
    overrides.settings.push_back(seed_setting(seed));
    const auto scene = load_scene(path.string(), overrides);
    RenderOptions options;
    options.spp = scene->spp;
    const ImageBuffer image = render_scene(*scene, options).film->resolve();
    Rendered result;
    const std::size_t stride = image.channels.size();
    for (std::size_t i = 0; i < image.pixels.size() / stride; ++i) {
        for (std::size_t c = 0; c < 3; ++c) result.rgb.push_back(image.pixels[i * stride + c]);
        result.alpha.push_back(image.pixels[i * stride + 3]);
    }
    return result;
}

std::string furnace_scene(double albedo, const std::string& integrator) {
    return R"({"isotrace": 1, "colour": {"working_space": "lin_rec709"},
      "film": {"resolution": [12, 12], "filter": {"type": "box"}},
      "camera": {"type": "perspective", "fov": 30, "look_at": {"eye": [0, 0, 6], "target": [0, 0, 0]}},
      "sampler": {"type": "independent"},
      "integrator": )" + integrator + R"(,
      "materials": {"m": {"type": "diffuse", "reflectance": )" + std::to_string(albedo) + R"(}},
      "lights": [{"type": "environment", "radiance": 1}],
      "objects": [{"material": "m", "shape": {"type": "sphere", "radius": 1}}]})";
}

// A convex diffuse object in a uniform environment of radiance 1: every reflected ray escapes, so each pixel
// sees albedo * 1 where it hits the sphere and 1 where it sees the environment.
TEST(PathIntegrator, WhiteFurnaceGivesOneEverywhere) {
    const Rendered image = render_text(furnace_scene(1.0, R"({"type": "path", "max_depth": 32})"), 64);
    double sum = 0;
    for (float v : image.rgb) {
        EXPECT_NEAR(v, 1.0f, 0.1f);
        sum += v;
    }
    EXPECT_NEAR(sum / double(image.rgb.size()), 1.0, 0.01);
}

TEST(PathIntegrator, HalfAlbedoSphereInAUniformEnvironmentGivesItsAlbedo) {
    const Rendered image = render_text(furnace_scene(0.5, R"({"type": "path"})"), 64);
    double hit_sum = 0;
    int hits = 0;
    for (std::size_t p = 0; p < image.alpha.size(); ++p) {
        if (image.alpha[p] == 1.0f) {
            for (int c = 0; c < 3; ++c) hit_sum += image.rgb[p * 3 + std::size_t(c)];
            hits += 3;
        } else if (image.alpha[p] == 0.0f) {
            for (int c = 0; c < 3; ++c) EXPECT_EQ(image.rgb[p * 3 + std::size_t(c)], 1.0f);
        }
    }
    ASSERT_GT(hits, 30);
    EXPECT_NEAR(hit_sum / hits, 0.5, 0.01);
}

// Inside a closed sphere of albedo 0.5 glowing with Le = 0.5: L = Le + 0.5 L, so L = 1 in every direction.
TEST(PathIntegrator, ViewerInsideAGlowingDiffuseSphereSeesOne) {
    const std::string scene = R"({"isotrace": 1, "colour": {"working_space": "lin_rec709"},
      "film": {"resolution": [8, 8], "filter": {"type": "box"}},
      "camera": {"type": "perspective", "fov": 90, "look_at": {"eye": [0.1, 0.2, 0.3], "target": [1, 0, 0]}},
      "sampler": {"type": "independent"},
      "integrator": {"type": "path", "max_depth": 64},
      "materials": {"glow": {"type": "diffuse", "reflectance": 0.5, "emission": 0.5, "two_sided_emission": true}},
      "objects": [{"material": "glow", "shape": {"type": "sphere", "radius": 2}}]})";
    const Rendered image = render_text(scene, 64);
    double sum = 0;
    for (float v : image.rgb) sum += v;
    EXPECT_NEAR(sum / double(image.rgb.size()), 1.0, 0.01);
}

// Records every dimension asked for; the values walk [0, 1) so that the paths go on.
class RecordingSampler final : public Sampler {
public:
    RecordingSampler() : Sampler(0) {}
    float sample(const PixelSampleKey&, uint32_t dimension) const override {
        asked.insert(dimension);
        return std::fmod(0.618034f * float(dimension + 1), 1.0f);
    }
    mutable std::set<uint32_t> asked;
};

// Inside a closed diffuse sphere lit by one point light, every path makes max_depth bounces. Two bounces own
// four blocks (light, the pair's directions, the pair's roulette, the second bounce's light): the light blocks
// are skipped (a delta light and Lambert read nothing from them), so is the roulette (off), and the directions of
// bounces 0-1 and 2-3 are the blocks 2 and 6, one 4-D point each.
TEST(PathIntegrator, TwoBouncesTakeTheirDirectionsFromOneBlockAndNothingUnread) {
    TemporaryDirectory directory("path_integrator");
    const auto path = directory.write("scene.json", R"({"isotrace": 1, "colour": {"working_space": "lin_rec709"},
      "film": {"resolution": [4, 4]},
      "camera": {"type": "perspective", "fov": 60, "look_at": {"eye": [0, 0, 0], "target": [0, 0, 1]}},
      "integrator": {"type": "path", "max_depth": 4, "russian_roulette_depth": 1024},
      "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "lights": [{"type": "point", "position": [0, 0.5, 0], "intensity": 1}],
      "objects": [{"material": "m", "shape": {"type": "sphere", "radius": 2}}]})");
    const auto scene = load_scene(path.string(), {});
    RecordingSampler sampler;
    SampleStream samples(sampler, {0, 0, 0});
    samples.next_2d();  // the camera's block: dimensions 0-3
    samples.next_2d();
    PrimaryHitRecord primary;
    scene->integrator->radiance(Ray{{0, 0, 0}, {0, 0, 1}}, *scene->scene, samples, primary);
    EXPECT_TRUE(primary.hit);
    EXPECT_EQ(sampler.asked, (std::set<uint32_t>{0, 1, 2, 3, 8, 9, 10, 11, 24, 25, 26, 27}));
}

// Irradiance at a point under the centre of a parallel square light (half side c, height h, radiance L), from the
// form factor of a rectangle with one corner above the point, times four quadrants.
double square_light_irradiance(double radiance, double c, double h) {
    const double x = c / h, y = c / h;
    const double corner = (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                           y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
                          (2 * std::numbers::pi);
    return std::numbers::pi * radiance * 4 * corner;
}

TEST(DirectIntegrator, SmallAreaLightMatchesClosedFormIrradiance) {
    const double radiance = 10, half_side = 0.25, height = 1, albedo = 0.8;
    // Orthographic camera looking straight down at the centre of the floor; light square faces down.
    const std::string scene = R"({"isotrace": 1, "colour": {"working_space": "lin_rec709"},
      "film": {"resolution": [1, 1], "filter": {"type": "box", "radius": 0.001}},
      "camera": {"type": "orthographic", "width": 0.0001, "look_at": {"eye": [0, 0.5, 0], "target": [0, 0, 0], "up": [0, 0, -1]}},
      "sampler": {"type": "sobol"},
      "integrator": {"type": "direct"},
      "materials": {"floor": {"type": "diffuse", "reflectance": 0.8},
                    "lamp": {"type": "emissive", "radiance": 10}},
      "objects": [
        {"material": "floor", "shape": {"type": "mesh", "positions": [[-5, 0, -5], [-5, 0, 5], [5, 0, 5], [5, 0, -5]],
                                       "triangles": [[0, 1, 2], [0, 2, 3]]}},
        {"material": "lamp", "shape": {"type": "mesh",
            "positions": [[-0.25, 1, -0.25], [0.25, 1, -0.25], [0.25, 1, 0.25], [-0.25, 1, 0.25]],
            "triangles": [[0, 1, 2], [0, 2, 3]]}}]})";
    const Rendered image = render_text(scene, 4096);
    const double expected = albedo / std::numbers::pi * square_light_irradiance(radiance, half_side, height);
    EXPECT_NEAR(image.rgb[0], expected, 0.005 * expected);
    EXPECT_NEAR(image.rgb[1], expected, 0.005 * expected);
}

// Mean squared error against a high-spp reference falls as 1/spp for independent sampling: the log-log slope
// over 4..64 spp, averaged over seeds, is close to -1.
TEST(PathIntegrator, SquaredErrorFallsAsOneOverSpp) {
    const std::string scene = R"({"isotrace": 1, "colour": {"working_space": "lin_rec709"},
      "film": {"resolution": [6, 6], "filter": {"type": "box"}},
      "camera": {"type": "perspective", "fov": 40, "look_at": {"eye": [0, 1, 5], "target": [0, 0.5, 0]}},
      "sampler": {"type": "independent"},
      "integrator": {"type": "path", "max_depth": 4},
      "materials": {"m": {"type": "diffuse", "reflectance": 0.7}, "lamp": {"type": "emissive", "radiance": 4}},
      "objects": [
        {"material": "m", "shape": {"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5}},
        {"material": "m", "shape": {"type": "mesh", "positions": [[-5, 0, -5], [-5, 0, 5], [5, 0, 5], [5, 0, -5]],
                                   "triangles": [[0, 1, 2], [0, 2, 3]]}},
        {"material": "lamp", "shape": {"type": "mesh", "positions": [[-1, 3, -1], [1, 3, -1], [1, 3, 1], [-1, 3, 1]],
                                      "triangles": [[0, 1, 2], [0, 2, 3]]}}]})";
    const Rendered reference = render_text(scene, 4096, 999);
    std::vector<double> log_spp, log_error;
    for (int spp : {4, 16, 64}) {
        double mse = 0;
        const int seeds = 6;
        for (int seed = 0; seed < seeds; ++seed) {
            const Rendered image = render_text(scene, spp, std::uint64_t(seed));
            for (std::size_t i = 0; i < image.rgb.size(); ++i) {
                const double d = image.rgb[i] - reference.rgb[i];
                mse += d * d;
            }
        }
        log_spp.push_back(std::log(double(spp)));
        log_error.push_back(std::log(mse / seeds));
    }
    // Least-squares slope.
    const double mx = (log_spp[0] + log_spp[1] + log_spp[2]) / 3, my = (log_error[0] + log_error[1] + log_error[2]) / 3;
    double sxy = 0, sxx = 0;
    for (int i = 0; i < 3; ++i) {
        sxy += (log_spp[std::size_t(i)] - mx) * (log_error[std::size_t(i)] - my);
        sxx += (log_spp[std::size_t(i)] - mx) * (log_spp[std::size_t(i)] - mx);
    }
    EXPECT_NEAR(sxy / sxx, -1.0, 0.2);
}

}  // namespace
}  // namespace isotrace

namespace isotrace {
namespace {

// Far from the origin, every point of a sunlit plane must receive the full direct light: no shadow acne from
// shadow rays re-hitting the plane they leave. A thin slab above a second plane must keep it fully dark: no
// light leaks through a 1 mm wall.
TEST(DirectIntegrator, NoShadowAcneFarFromTheOriginAndNoLeaksThroughThinWalls) {
    const std::string scene = R"({"isotrace": 1, "colour": {"working_space": "lin_rec709"},
      "film": {"resolution": [16, 16], "filter": {"type": "box"}},
      "camera": {"type": "perspective", "fov": 30, "look_at": {"eye": [1000.37, 31.3, -1990.77], "target": [1000.1, 0, -2000.3]}},
      "integrator": {"type": "direct"},
      "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "lights": [{"type": "directional", "direction": [-1, -2, 0.5], "irradiance": 3}],
      "objects": [{"material": "m", "shape": {"type": "mesh",
        "positions": [[980, 0, -2020], [980, 0, -1980], [1020, 0, -1980], [1020, 0, -2020]],
        "triangles": [[0, 1, 2], [0, 2, 3]]}}]})";
    const Rendered lit = render_text(scene, 4);
    const Vec3f to_light = normalize(Vec3f(1, 2, -0.5f));
    const float expected = 0.5f / float(std::numbers::pi) * 3.0f * to_light.y;
    for (float v : lit.rgb) EXPECT_NEAR(v, expected, 1e-5f * expected);

    // A floor under a much larger 1 mm slab whose top is in the sun: every path below stays in the dark.
    const std::string slab = R"({"isotrace": 1, "colour": {"working_space": "lin_rec709"},
      "film": {"resolution": [16, 16], "filter": {"type": "box"}},
      "camera": {"type": "orthographic", "width": 4, "look_at": {"eye": [0, 0.5, 0], "target": [0, 0, 0], "up": [0, 0, -1]}},
      "integrator": {"type": "path", "max_depth": 4},
      "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "lights": [{"type": "directional", "direction": [0.3, -1, 0.2], "irradiance": 3}],
      "objects": [
        {"material": "m", "shape": {"type": "mesh", "positions": [[-10, 0, -10], [-10, 0, 10], [10, 0, 10], [10, 0, -10]],
                                   "triangles": [[0, 1, 2], [0, 2, 3]]}},
        {"material": "m", "shape": {"type": "mesh", "positions": [[-50, 1, -50], [-50, 1, 50], [50, 1, 50], [50, 1, -50],
                                                                 [-50, 1.001, -50], [-50, 1.001, 50], [50, 1.001, 50], [50, 1.001, -50]],
                                   "triangles": [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7]]}}]})";
    const Rendered shaded = render_text(slab, 4);
    for (float v : shaded.rgb) EXPECT_EQ(v, 0.0f);
}

}  // namespace
}  // namespace isotrace

namespace isotrace {
namespace {

CounterTotals rays_of(const std::string& scene_text, int spp) {
    counters::reset();
    render_text(scene_text, spp);
    return counters::totals();
}

std::string point_lit_scene(const std::string& integrator, const std::string& extra_lights) {
    return R"({"isotrace": 1, "colour": {"working_space": "lin_rec709"},
      "film": {"resolution": [8, 8], "filter": {"type": "box"}},
      "camera": {"type": "perspective", "fov": 40, "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
      "sampler": {"type": "independent"},
      "integrator": )" + integrator + R"(,
      "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "lights": [{"type": "point", "position": [1, 2, 3], "intensity": 10})" + extra_lights + R"(],
      "objects": [{"material": "m", "shape": {"type": "mesh", "positions": [[-9, -9, -1], [9, -9, -1], [9, 9, -1], [-9, 9, -1]],
                                              "triangles": [[0, 1, 2], [0, 2, 3]]}}]})";
}

// Under delta lights alone a path's last ray could only find emission, and there is none to find: it is not
// traced. The film covers the plane, so every camera ray hits it and each pixel sample casts one shadow ray per
// bounce. An environment light makes the last ray worth tracing again.
TEST(PathIntegrator, TracesNoLastRayWhenOnlyDeltaLightsEmit) {
    const int spp = 4;
    const std::uint64_t samples = 8 * 8 * spp;
    const CounterTotals direct = rays_of(point_lit_scene(R"({"type": "direct"})", ""), spp);
    EXPECT_EQ(direct.camera_rays, samples);
    EXPECT_EQ(direct.secondary_rays, 0u);
    EXPECT_EQ(direct.shadow_rays, samples);

    // Two bounces: the only bounce ray is the first one (it leaves the plane and escapes, ending the path).
    const CounterTotals path = rays_of(point_lit_scene(R"({"type": "path", "max_depth": 2})", ""), spp);
    EXPECT_EQ(path.secondary_rays, samples);

    const CounterTotals lit_by_sky =
        rays_of(point_lit_scene(R"({"type": "direct"})", R"(, {"type": "environment", "radiance": 1})"), spp);
    EXPECT_EQ(lit_by_sky.secondary_rays, samples);
}

// A path's contributions are all multiples of its throughput. Between a red floor and a green ceiling, a path
// that has bounced off the floor and reaches the ceiling carries red only and the ceiling reflects green only:
// nothing it could add is non-zero, so it traces no shadow ray there and no ray beyond. Each sample then casts
// one shadow ray (at the floor) and one bounce ray (to the ceiling; a grazing one may escape) instead of a path
// of eight.
TEST(PathIntegrator, TracesNothingMoreOnceTheThroughputIsBlack) {
    const int spp = 4;
    const std::uint64_t samples = 8 * 8 * spp;
    const std::string scene = R"({"isotrace": 1, "colour": {"working_space": "lin_rec709"},
      "film": {"resolution": [8, 8], "filter": {"type": "box"}},
      "camera": {"type": "perspective", "fov": 40, "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
      "sampler": {"type": "independent"},
      "integrator": {"type": "path", "max_depth": 8, "russian_roulette_depth": 1024},
      "materials": {"red": {"type": "diffuse", "reflectance": [1, 0, 0]},
                    "green": {"type": "diffuse", "reflectance": [0, 1, 0]}},
      "lights": [{"type": "point", "position": [1, 2, 3], "intensity": 10}],
      "objects": [
        {"material": "red", "shape": {"type": "mesh", "positions": [[-1000, -1000, -1], [1000, -1000, -1], [1000, 1000, -1], [-1000, 1000, -1]],
                                      "triangles": [[0, 1, 2], [0, 2, 3]]}},
        {"material": "green", "shape": {"type": "mesh", "positions": [[-1000, -1000, 10], [1000, -1000, 10], [1000, 1000, 10], [-1000, 1000, 10]],
                                        "triangles": [[0, 1, 2], [0, 2, 3]]}}]})";
    const CounterTotals rays = rays_of(scene, spp);
    EXPECT_EQ(rays.camera_rays, samples);
    EXPECT_EQ(rays.shadow_rays, samples);
    EXPECT_LE(rays.secondary_rays, samples);
    EXPECT_GE(rays.secondary_rays, samples * 99 / 100);

    // The image is what the floor's own shadow rays give: the red channel only.
    const Rendered image = render_text(scene, spp);
    for (std::size_t p = 0; p < image.alpha.size(); ++p) {
        EXPECT_GT(image.rgb[p * 3], 0.0f);
        EXPECT_EQ(image.rgb[p * 3 + 1], 0.0f);
        EXPECT_EQ(image.rgb[p * 3 + 2], 0.0f);
    }
}

}  // namespace
}  // namespace isotrace

namespace isotrace {
namespace {

class SamplesInStep : public ::testing::TestWithParam<std::string> {};

// Samples are traced as paths in step whose rays are packet queries, the live paths closing up as others end
// (triangle meshes, user geometries answering packets, placements, point, area and environment lights, delta and
// layered BSDFs): each sample must keep radiance()'s bits, its AOV record and the sampler dimensions it took,
// whatever its companions, for groups of a whole pixel and of several pixels' samples, and a shorter last one.
TEST_P(SamplesInStep, GiveEachSampleRadiancesBits) {
    const auto loaded = load_scene(std::string(ISOTRACE_SCENES_DIR) + "/" + GetParam() + ".json");
    const std::size_t group = loaded->integrator->samples_traced_together(*loaded->scene);
    ASSERT_EQ(group, Integrator::kMaxSamplesTogether);
    const int width = loaded->film.raster.width, height = loaded->film.raster.height;
    std::vector<std::array<int, 2>> pixels;
    for (int y = height / 10; y < height; y += height / 5)
        for (int x = width / 14; x < width; x += width / 7) pixels.push_back({x, y});
    const auto trace = [&](std::span<const Ray> rays, std::span<SampleStream> streams,
                           std::span<PrimaryHitRecord> primary, std::span<Rgb> radiance) {
        loaded->integrator->radiance_of_samples(rays, *loaded->scene, streams, primary, radiance);
    };
    // Eleven samples a pixel: groups of several pixels' samples, a pixel's split between two groups.
    EXPECT_GT(testing::expect_groups_match_single_paths(*loaded, pixels, 11, group, trace), 0);
    // A whole group of one pixel's samples, and packets of eight from it.
    const std::array<std::array<int, 2>, 1> one{pixels[pixels.size() / 2]};
    testing::expect_groups_match_single_paths(*loaded, one, std::uint32_t(group), group, trace);
    testing::expect_groups_match_single_paths(*loaded, one, 8, 8, trace);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SamplesInStep,
                         ::testing::Values("embree_cornell_box", "primitives", "materials", "csg_cup", "metacube_dog",
                                           "instances", "lookdev", "showcase"));

}  // namespace
}  // namespace isotrace
