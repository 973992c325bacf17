// The packet path tracer against the scalar one: on flat Lambertian scenes, eight paths in SIMD lanes must give
// PathIntegrator::radiance's bits for every sample, whatever its companions, light count, depth, roulette and
// clamp; and RenderScene must offer the packets only for scenes they handle.
#include "integrators/path/flat_lambertian_packets.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/samples_together.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

using testing::SceneFile;

// A closed room of triangle meshes (one mirrored by its transform, which flips its winding when baked), a box on
// the floor, reflectances with black channels, and one or two point lights.
std::string room(const std::string& integrator, const std::string& lights, const std::string& extra_material = "",
                 const std::string& extra_object = "") {
    return R"({"isotrace": 1, "colour": {"working_space": "lin_rec709"},
      "film": {"resolution": [24, 16], "filter": {"type": "gaussian"}},
      "camera": {"type": "perspective", "fov": 70, "look_at": {"eye": [0, 1, 2.5], "target": [0, 1, 0]}},
      "integrator": )" + integrator + R"(,
      "materials": {"white": {"type": "diffuse", "reflectance": 0.9},
                    "red": {"type": "diffuse", "reflectance": [0.8, 0, 0]},
                    "teal": {"type": "diffuse", "reflectance": [0, 0.5, 0.6]})" + extra_material + R"(},
      "lights": [)" + lights + R"(],
      "objects": [
        {"name": "shell", "material": "white", "shape": {"type": "mesh",
          "positions": [[-2,0,-2],[2,0,-2],[2,0,3],[-2,0,3],[-2,2.5,-2],[2,2.5,-2],[2,2.5,3],[-2,2.5,3]],
          "triangles": [[0,1,2],[0,2,3],[4,6,5],[4,7,6],[0,4,5],[0,5,1],[3,2,6],[3,6,7]]}},
        {"name": "left", "material": "red", "shape": {"type": "mesh",
          "positions": [[-2,0,-2],[-2,0,3],[-2,2.5,3],[-2,2.5,-2]], "triangles": [[0,1,2],[0,2,3]]}},
        {"name": "right", "material": "teal", "transform": {"scale": [-1, 1, 1]}, "shape": {"type": "mesh",
          "positions": [[-2,0,-2],[-2,0,3],[-2,2.5,3],[-2,2.5,-2]], "triangles": [[0,1,2],[0,2,3]]}},
        {"name": "box", "material": "white", "transform": {"translate": [0.3, 0, -0.5], "rotate": {"axis": [0, 1, 0], "angle": 25}, "scale": 0.7},
          "shape": {"type": "mesh",
            "positions": [[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1]],
            "triangles": [[0,2,3],[0,3,1],[4,5,7],[4,7,6],[0,1,5],[0,5,4],[2,6,7],[2,7,3],[0,4,6],[0,6,2],[1,3,7],[1,7,5]]}})" +
           extra_object + R"(
      ]})";
}

const std::string kOneLight = R"({"type": "point", "position": [0.5, 2.2, 0.5], "intensity": 3})";
const std::string kTwoLights = kOneLight + R"(, {"type": "point", "position": [-1.2, 1.5, 1.5], "intensity": [1, 2, 0.5]})";

// Every other pixel of every third row, samples [0, count) traced by `kernel` against radiance() one at a time.
int expect_packets_match_single_paths(const LoadedScene& loaded, std::uint32_t count, FlatLambertianKernel kernel,
                                      const PathSettings& settings) {
    EXPECT_NE(loaded.scene->flat_lambertian(), nullptr);
    std::vector<std::array<int, 2>> pixels;
    for (int y = 0; y < 16; y += 3)
        for (int x = 0; x < 24; x += 2) pixels.push_back({x, y});
    return testing::expect_groups_match_single_paths(
        loaded, pixels, count,
        [&](std::span<const Ray> rays, std::span<SampleStream> streams, std::span<PrimaryHitRecord> primary,
            std::span<Rgb> radiance) {
            kernel(settings, rays, *loaded.scene, *loaded.scene->flat_lambertian(), streams, primary, radiance);
        });
}

std::string path_integrator(const PathSettings& settings) {
    return R"({"type": "path", "max_depth": )" + std::to_string(settings.max_depth) +
           R"(, "russian_roulette_depth": )" + std::to_string(settings.russian_roulette_depth) +
           R"(, "clamp": )" + std::to_string(settings.clamp) + "}";
}

struct Case {
    std::string name;
    PathSettings settings;
    std::string lights;
    friend void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }
};

class PacketsMatchSinglePaths : public ::testing::TestWithParam<Case> {};

// Both builds of the kernel (on a CPU without AVX2 the chosen one is the baseline one).
TEST_P(PacketsMatchSinglePaths, BitForBit) {
    const SceneFile file(room(path_integrator(GetParam().settings), GetParam().lights));
    const auto loaded = load_scene(file.path());
    EXPECT_GT(expect_packets_match_single_paths(*loaded, 19, &baseline_isa::trace_flat_lambertian_paths,
                                                GetParam().settings), 100);
    SCOPED_TRACE(flat_lambertian_kernel_name());
    EXPECT_GT(expect_packets_match_single_paths(*loaded, 19, flat_lambertian_kernel(), GetParam().settings), 100);
}

INSTANTIATE_TEST_SUITE_P(
    Settings, PacketsMatchSinglePaths,
    ::testing::Values(Case{"OneLightNoRoulette", {8, 1024, 0}, kOneLight},
                      Case{"TwoLightsWithRoulette", {12, 2, 0}, kTwoLights},
                      Case{"OneLightClamped", {5, 4, 0.05f}, kOneLight},
                      Case{"TwoLightsDirect", {1, 1024, 0}, kTwoLights},
                      Case{"OddDepth", {3, 1, 0}, kTwoLights}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

// Scenes without lights trace paths that carry nothing, packets or not.
TEST(FlatLambertianPackets, SceneWithoutLightsIsBlack) {
    const PathSettings settings{4, 4, 0};
    const SceneFile file(room(path_integrator(settings), ""));
    const auto loaded = load_scene(file.path());
    EXPECT_EQ(expect_packets_match_single_paths(*loaded, 9, flat_lambertian_kernel(), settings), 0);
}

// The AVX2 build is the one chosen where the CPU has AVX2.
TEST(FlatLambertianPackets, KernelForThisCpu) {
    EXPECT_EQ(std::string(flat_lambertian_kernel_name()), __builtin_cpu_supports("avx2") ? "avx2" : "baseline x86-64");
}

// Whole renders through the tile renderer: the same bits for any thread count and tile size, and for a render
// stopped at 3 samples per pixel and resumed to 13, whose samples are grouped differently (its passes end at 3
// as well as at the powers of two).
TEST(FlatLambertianPackets, RendersIdenticallyAcrossThreadsTilesAndResumption) {
    const SceneFile file(room(R"({"type": "path", "max_depth": 6})", kTwoLights));
    SceneOverrides overrides;
    overrides.settings.push_back(spp_setting(13));
    const auto loaded = load_scene(file.path(), overrides);
    ASSERT_NE(loaded->scene->flat_lambertian(), nullptr);
    const auto render = [&](int threads, int tile_size, std::unique_ptr<Film> film, int spp) {
        RenderOptions options;
        options.tile_size = tile_size;
        options.spp = spp;
        tbb::task_arena arena(threads);
        RenderResult result;
        arena.execute([&] { result = render_scene(*loaded, options, std::move(film)); });
        return std::move(result.film);
    };
    const std::vector<float> reference = render(1, 64, nullptr, 13)->resolve().pixels;
    EXPECT_EQ(render(2, 5, nullptr, 13)->resolve().pixels, reference);
    EXPECT_EQ(render(2, 16, render(1, 7, nullptr, 3), 13)->resolve().pixels, reference);
}

// The render statistics say when and how samples are traced together.
TEST(FlatLambertianPackets, DescribedForTheStatistics) {
    const SceneFile flat_file(room(R"({"type": "path"})", kOneLight));
    const auto flat = load_scene(flat_file.path());
    EXPECT_EQ(flat->integrator->samples_traced_together(*flat->scene), std::size_t(kLanes));
    EXPECT_NE(flat->integrator->packet_description(*flat->scene).find(flat_lambertian_kernel_name()), std::string::npos);
    const SceneFile other_file(room(R"({"type": "path"})", kOneLight + R"(, {"type": "environment", "radiance": 0.1})"));
    const auto other = load_scene(other_file.path());
    EXPECT_EQ(other->integrator->samples_traced_together(*other->scene), std::size_t(kLanes));
    EXPECT_NE(other->integrator->packet_description(*other->scene).find("in step"), std::string::npos);
}

// Anything the packets do not shade keeps the scene on the general loop.
TEST(FlatLambertianPackets, OfferedOnlyForFlatMeshesDiffuseMaterialsAndPointLights) {
    const std::string path = R"({"type": "path"})";
    const auto flat = [&](const std::string& text) {
        const SceneFile file(text);
        return load_scene(file.path())->scene->flat_lambertian() != nullptr;
    };
    EXPECT_TRUE(flat(room(path, kTwoLights)));
    EXPECT_FALSE(flat(room(path, kOneLight + R"(, {"type": "directional", "direction": [0, -1, 0], "irradiance": 1})")));
    EXPECT_FALSE(flat(room(path, kOneLight + R"(, {"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": 1})")));
    EXPECT_FALSE(flat(room(path, kOneLight + R"(, {"type": "environment", "radiance": 0.1})")));
    const std::string sphere = R"(, {"material": "white", "shape": {"type": "sphere", "radius": 0.2}})";
    EXPECT_FALSE(flat(room(path, kOneLight, "", sphere)));
    const std::string lamp_material = R"(, "lamp": {"type": "diffuse", "reflectance": 0.5, "emission": 2})";
    const std::string lamp = R"(, {"material": "lamp", "shape": {"type": "mesh",
        "positions": [[0,2.4,0],[0.2,2.4,0],[0,2.4,0.2]], "triangles": [[0,1,2]]}})";
    EXPECT_FALSE(flat(room(path, kOneLight, lamp_material, lamp)));
    const std::string coated_material = R"(, "coated": {"type": "plastic", "reflectance": 0.4})";
    const std::string coated = R"(, {"material": "coated", "shape": {"type": "mesh",
        "positions": [[0,0.01,0],[0.2,0.01,0],[0,0.01,0.2]], "triangles": [[0,2,1]]}})";
    EXPECT_FALSE(flat(room(path, kOneLight, coated_material, coated)));
    const std::string smooth = R"(, {"material": "white", "shape": {"type": "mesh",
        "positions": [[0,0.01,0],[0.2,0.01,0],[0,0.01,0.2]], "normals": [[0,1,0],[0,1,0],[0,1,0]], "triangles": [[0,2,1]]}})";
    EXPECT_FALSE(flat(room(path, kOneLight, "", smooth)));
}

}  // namespace
}  // namespace isotrace
