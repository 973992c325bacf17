// render_scene(): bit-identical images for any thread count, tile size or time budget; exact sample budgets;
// cancellation from the progress callback; time budgets; NaN samples counted and dropped; the depth AOV.
#include "renderer/render/tile_renderer.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "renderer/core/render_counters.h"
#include "renderer/plugin/integrator.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/scene_files.h"
#include "tests/support/test_time_scale.h"

namespace isotrace {
namespace {

// ---- test-only integrators --------------------------------------------------------------------------------

// Radiance 1 for rays going left; for rays going right NaN (upwards), +inf (well below) or a finite value whose
// square overflows a float (just below); counts what it returned.
std::atomic<std::uint64_t> g_bad_samples{0}, g_huge_samples{0};
class BadValueIntegrator final : public Integrator {
public:
    Rgb radiance(const Ray& ray, const RenderScene&, SampleStream&, PrimaryHitRecord&) const override {
        if (ray.direction.x <= 0) return Rgb(1.0f);
        ++g_bad_samples;
        if (ray.direction.y > 0) return Rgb(std::numeric_limits<float>::quiet_NaN(), 1, 1);
        if (ray.direction.y < -0.05f) return Rgb(1, std::numeric_limits<float>::infinity(), 1);
        ++g_huge_samples;
        return Rgb(1, 1, 3e30f);
    }
};

// Renders black, but once `g_free_calls` calls have been made every further call waits until the render's
// cancel flag is raised: the first passes complete, and the pass after them is cut short deterministically.
// `g_waiting_calls` counts the calls that have started waiting, so a test can cancel only once one has.
std::atomic<std::int64_t> g_free_calls{0};
std::atomic<bool> g_cancel{false};
std::atomic<int> g_waiting_calls{0};
class WaitForCancelIntegrator final : public Integrator {
public:
    Rgb radiance(const Ray&, const RenderScene&, SampleStream&, PrimaryHitRecord&) const override {
        if (g_free_calls.fetch_sub(1) <= 0) {
            ++g_waiting_calls;
            while (!g_cancel.load()) std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
        return Rgb(0.5f);
    }
};

// Sleeps, then returns the sample's own random numbers as colour: slow enough for stops to land mid-pass, and
// every sample different, so that adding a pixel's samples in another order would change its bits.
class SlowRandomIntegrator final : public Integrator {
public:
    Rgb radiance(const Ray&, const RenderScene&, SampleStream& samples, PrimaryHitRecord&) const override {
        std::this_thread::sleep_for(std::chrono::microseconds(300));
        const auto [u, v] = samples.next_2d();
        return Rgb(u, v, u * v + 0.1f);
    }
};

// White where the renderer asked for the first hit's albedo, black where it did not.
class AlbedoKeptIntegrator final : public Integrator {
public:
    Rgb radiance(const Ray&, const RenderScene&, SampleStream&, PrimaryHitRecord& primary) const override {
        return Rgb(primary.keeps_albedo ? 1.0f : 0.0f);
    }
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(integrator_registry, "test_slow_random", "test only: 300 us per sample, random colour",
                         [](const SceneNode&) -> std::unique_ptr<Integrator> {
                             return std::make_unique<SlowRandomIntegrator>();
                         })
ISOTRACE_REGISTER_PLUGIN(integrator_registry, "test_bad_values", "test only: NaN/inf radiance for rays going right",
                         [](const SceneNode&) -> std::unique_ptr<Integrator> {
                             return std::make_unique<BadValueIntegrator>();
                         })
ISOTRACE_REGISTER_PLUGIN(integrator_registry, "test_albedo_kept", "test only: white where the albedo is kept",
                         [](const SceneNode&) -> std::unique_ptr<Integrator> {
                             return std::make_unique<AlbedoKeptIntegrator>();
                         })
ISOTRACE_REGISTER_PLUGIN(integrator_registry, "test_wait_for_cancel", "test only: blocks until cancelled",
                         [](const SceneNode&) -> std::unique_ptr<Integrator> {
                             return std::make_unique<WaitForCancelIntegrator>();
                         })

namespace {

using testing::kTestTimeScale;
using testing::SceneFile;

// Spheres (baked and instanced), meshes, point and directional lights, an emitter and the preview integrator.
std::string test_scene(const std::string& film_extra = "", const std::string& integrator = "") {
    return R"({"isotrace": 1,
  "film": {"resolution": [48, 40], "spp": 8, "crop": [0.1, 0.9, 0.05, 0.95], "aovs": ["all"],
           "filter": {"type": "gaussian"})" +
           film_extra + R"(},
  "camera": {"type": "perspective", "fov": 50, "look_at": {"eye": [0.3, 1.5, 5], "target": [0, 0.4, 0]}},
  "sampler": {"type": "sobol", "seed": 7},
  "integrator": )" +
           (integrator.empty()
                ? std::string(R"({"type": "preview", "ambient": 0.3, "ambient_samples": 2, "background": [0.1, 0.2, 0.3]})")
                : integrator) +
           R"(,
  "materials": {
    "red": {"type": "diffuse", "reflectance": [0.8, 0.2, 0.2]},
    "grey": {"type": "diffuse", "reflectance": 0.6},
    "lamp": {"type": "emissive", "radiance": [4, 3, 2]}
  },
  "lights": [
    {"type": "point", "position": [2, 3, 2], "intensity": 12},
    {"type": "directional", "direction": [-1, -2, -0.5], "irradiance": [1, 0.9, 0.8]}
  ],
  "objects": [
    {"name": "floor", "material": "grey", "shape": {"type": "mesh",
      "positions": [[-4, 0, -4], [4, 0, -4], [4, 0, 4], [-4, 0, 4]], "triangles": [[0, 2, 1], [0, 3, 2]]}},
    {"name": "balls", "material": "red", "shape": {"type": "sphere",
      "spheres": [{"center": [-0.8, 0.5, 0], "radius": 0.5}, {"center": [0.9, 0.35, 0.6], "radius": 0.35}]}},
    {"name": "egg", "material": "grey", "transform": {"translate": [0.2, 0.9, -1], "scale": [0.3, 0.6, 0.3]},
      "shape": {"type": "sphere"}},
    {"name": "box", "material": "lamp", "transform": {"translate": [1.2, 0, -1.2], "rotate": {"axis": [0, 1, 0], "angle": 30}, "scale": 0.5},
      "shape": {"type": "mesh",
        "positions": [[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1]],
        "triangles": [[0,2,3],[0,3,1],[4,5,7],[4,7,6],[0,1,5],[0,5,4],[2,6,7],[2,7,3],[0,4,6],[0,6,2],[1,3,7],[1,7,5]]}}
  ]})";
}

// test_scene() with this integrator, loaded at this spp and resolution.
std::unique_ptr<LoadedScene> load_test_scene(int spp, RasterSize resolution, const std::string& integrator) {
    SceneOverrides overrides;
    overrides.settings.push_back(spp_setting(spp));
    overrides.settings.push_back(resolution_setting(resolution));
    const SceneFile file(test_scene("", integrator));
    return load_scene(file.path(), overrides);
}

RenderResult render_with_threads(const LoadedScene& scene, int threads, RenderOptions options,
                                 std::unique_ptr<Film> film = {}) {
    tbb::task_arena arena(threads);
    RenderResult result;
    arena.execute([&] { result = render_scene(scene, options, std::move(film)); });
    return result;
}

RenderOptions options_for(const LoadedScene& scene, int tile_size) {
    RenderOptions options;
    options.tile_size = tile_size;
    options.spp = scene.spp;
    return options;
}

// A stop_at_pass_end that never stops and records the sample count of each pass end it is asked at.
std::function<bool(const Film&)> recording_pass_ends(std::vector<std::uint32_t>& asked) {
    return [&asked](const Film& film) {
        asked.push_back(film.sample_count_range().min);
        return false;
    };
}

int channel(const ImageBuffer& image, const std::string& name) {
    for (std::size_t i = 0; i < image.channels.size(); ++i)
        if (image.channels[i] == name) return int(i);
    ADD_FAILURE() << "no channel " << name;
    return 0;
}

void expect_bit_identical(const ImageBuffer& a, const ImageBuffer& b, const std::string& what) {
    ASSERT_EQ(a.width, b.width) << what;
    ASSERT_EQ(a.height, b.height) << what;
    ASSERT_EQ(a.channels, b.channels) << what;
    ASSERT_EQ(a.pixels.size(), b.pixels.size()) << what;
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0) << what;
}

TEST(TileRenderer, ImagesAreBitIdenticalForAnyThreadCountTileSizeAndBudget) {
    const SceneFile file(test_scene());
    const auto scene = load_scene(file.path());
    ASSERT_EQ(scene->film.crop.x0, 5);
    ASSERT_EQ(scene->film.crop.x1, 44);
    ASSERT_EQ(scene->film.crop.y0, 2);
    ASSERT_EQ(scene->film.crop.y1, 38);
    ASSERT_EQ(scene->spp, 8);
    const RenderResult reference = render_with_threads(*scene, 1, options_for(*scene, 32));
    ASSERT_EQ(reference.completed_spp, 8);
    const ImageBuffer expected = reference.film->resolve();
    ASSERT_EQ(expected.width, 39);
    ASSERT_EQ(expected.height, 36);
    ASSERT_EQ(expected.channels.size(), 4u + 3 + 3 + 1 + 3 + 1 + 1 + 1 + 3);

    // The image is not trivial: several objects, misses and hits, varying colours.
    const int object_channel = channel(expected, "objectId");
    std::set<float> ids;
    for (std::size_t i = 0; i < std::size_t(expected.width * expected.height); ++i)
        ids.insert(expected.pixels[i * expected.channels.size() + std::size_t(object_channel)]);
    EXPECT_GE(ids.size(), 4u);

    for (int threads : {1, 2}) {
        for (int tile : {1, 7, 32, 64}) {
            const RenderResult result = render_with_threads(*scene, threads, options_for(*scene, tile));
            EXPECT_EQ(result.completed_spp, 8);
            EXPECT_FALSE(result.partial);
            EXPECT_FALSE(result.cancelled);
            expect_bit_identical(result.film->resolve(), expected,
                                 std::to_string(threads) + " threads, tile " + std::to_string(tile));
        }
    }
    // A generous time budget changes how the samples are split into passes, not the image.
    for (int threads : {1, 2}) {
        RenderOptions options = options_for(*scene, 7);
        options.time_budget_seconds = 1000.0;
        const RenderResult result = render_with_threads(*scene, threads, options);
        EXPECT_EQ(result.completed_spp, 8);
        expect_bit_identical(result.film->resolve(), expected, "time budget, " + std::to_string(threads) + " threads");
    }
    // A progress callback does not disturb anything either.
    RenderOptions options = options_for(*scene, 5);
    std::atomic<int> calls{0};
    options.on_progress = [&](const RenderProgress&) { ++calls; };
    expect_bit_identical(render_with_threads(*scene, 2, options).film->resolve(), expected, "with progress");
}

TEST(TileRenderer, ImagesDependOnTheSeed) {
    // The determinism test above would pass trivially if nothing were random: a different seed must differ.
    const SceneFile a(test_scene()), b(test_scene());
    SceneOverrides other_seed;
    other_seed.settings.push_back(seed_setting(8));
    const auto scene_a = load_scene(a.path());
    const auto scene_b = load_scene(b.path(), other_seed);
    const ImageBuffer ia = render_with_threads(*scene_a, 2, options_for(*scene_a, 16)).film->resolve();
    const ImageBuffer ib = render_with_threads(*scene_b, 2, options_for(*scene_b, 16)).film->resolve();
    ASSERT_EQ(ia.pixels.size(), ib.pixels.size());
    EXPECT_NE(std::memcmp(ia.pixels.data(), ib.pixels.data(), ia.pixels.size() * sizeof(float)), 0);
}

TEST(TileRenderer, SampleBudgetIsMetExactly) {
    for (int spp : {1, 2, 5, 13}) {
        SceneOverrides overrides;
        overrides.settings.push_back(spp_setting(spp));
        overrides.settings.push_back(resolution_setting(RasterSize{20, 12}));
        const SceneFile file(test_scene());
        const auto scene = load_scene(file.path(), overrides);
        for (int threads : {1, 2}) {
            const RenderResult result = render_with_threads(*scene, threads, options_for(*scene, 3));
            EXPECT_EQ(result.completed_spp, spp);
            EXPECT_FALSE(result.partial);
            // Passes of 1, 1, 2, 4, ... samples, the last one cut to the budget.
            int passes = 0;
            for (int done = 0; done < spp; done += std::min(spp - done, std::max(1, done))) ++passes;
            EXPECT_EQ(result.passes, passes) << spp;
            const PixelBounds& crop = scene->film.crop;
            for (int y = crop.y0; y < crop.y1; ++y)
                for (int x = crop.x0; x < crop.x1; ++x) ASSERT_EQ(result.film->sample_count(x, y), std::uint32_t(spp));
            ImageBuffer image = result.film->resolve();
            const int count = channel(image, "sampleCount");
            for (int y = 0; y < image.height; ++y)
                for (int x = 0; x < image.width; ++x) ASSERT_EQ(image.pixel(x, y)[count], float(spp));
        }
    }
}

TEST(TileRenderer, CancellingFromTheProgressCallbackStopsMidPass) {
    SceneOverrides overrides;
    overrides.settings.push_back(spp_setting(64));
    overrides.settings.push_back(resolution_setting(RasterSize{12, 10}));
    const SceneFile file(test_scene("", R"({"type": "test_wait_for_cancel"})"));
    const auto scene = load_scene(file.path(), overrides);
    const std::int64_t pixels = scene->film.crop.area();
    for (int threads : {1, 2}) {
        g_cancel = false;
        g_free_calls = 2 * pixels;  // passes 1 and 2 (one sample each) run freely; pass 3 waits
        g_waiting_calls = 0;
        RenderOptions options = options_for(*scene, 2);
        options.cancel = &g_cancel;
        std::atomic<int> calls{0};
        std::chrono::steady_clock::time_point cancelled_at;  // read after the render joined the watcher thread
        // Cancels at the first report after pass 3 began waiting, however slowly passes 1 and 2 ran (the
        // watcher reports about 5 times a second for as long as the render lasts).
        options.on_progress = [&](const RenderProgress& progress) {
            ++calls;
            EXPECT_GE(progress.fraction, 0.0);
            EXPECT_LE(progress.fraction, 1.0);
            if (g_waiting_calls > 0 && !g_cancel) {
                cancelled_at = std::chrono::steady_clock::now();
                g_cancel = true;
            }
        };
        const RenderResult result = render_with_threads(*scene, threads, options);
        const double seconds_after_cancel =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - cancelled_at).count();
        EXPECT_GE(calls.load(), 1);
        EXPECT_TRUE(result.cancelled);
        EXPECT_TRUE(result.partial);
        EXPECT_EQ(result.completed_spp, 2);
        EXPECT_EQ(result.passes, 3);
        EXPECT_LT(seconds_after_cancel, 1.5 * kTestTimeScale);
        // Every pixel has the completed samples; the samples in flight when the flag was raised (one per
        // thread) were finished, and nothing after them was started.
        EXPECT_EQ(result.max_spp, 3);
        int in_flight = 0;
        const PixelBounds& crop = scene->film.crop;
        for (int y = crop.y0; y < crop.y1; ++y)
            for (int x = crop.x0; x < crop.x1; ++x) {
                const std::uint32_t n = result.film->sample_count(x, y);
                ASSERT_TRUE(n == 2 || n == 3) << n;
                in_flight += n == 3;
            }
        EXPECT_GE(in_flight, 1);
        EXPECT_LE(in_flight, threads);
    }
}

TEST(TileRenderer, CancelBeforeTheStartRendersNothing) {
    SceneOverrides overrides;
    overrides.settings.push_back(resolution_setting(RasterSize{8, 8}));
    const SceneFile file(test_scene());
    const auto scene = load_scene(file.path(), overrides);
    std::atomic<bool> cancel{true};
    RenderOptions options = options_for(*scene, 4);
    options.cancel = &cancel;
    const RenderResult result = render_with_threads(*scene, 2, options);
    EXPECT_TRUE(result.cancelled);
    EXPECT_FALSE(result.partial);
    EXPECT_EQ(result.completed_spp, 0);
    EXPECT_EQ(result.passes, 0);
    EXPECT_EQ(result.film->sample_count(3, 3), 0u);
}

TEST(TileRenderer, TimeBudgetEndsTheRender) {
    SceneOverrides overrides;
    overrides.settings.push_back(spp_setting(1 << 24));
    overrides.settings.push_back(resolution_setting(RasterSize{12, 10}));
    const SceneFile file(test_scene());
    const auto scene = load_scene(file.path(), overrides);
    RenderOptions options = options_for(*scene, 4);
    const double budget = 0.3 * kTestTimeScale;
    options.time_budget_seconds = budget;
    std::vector<RenderProgress> reports;
    std::mutex mutex;
    options.on_progress = [&](const RenderProgress& p) {
        std::lock_guard lock(mutex);
        reports.push_back(p);
    };
    const RenderResult result = render_with_threads(*scene, 2, options);
    EXPECT_FALSE(result.cancelled);
    EXPECT_TRUE(result.out_of_time);
    EXPECT_GT(result.completed_spp, 1);
    EXPECT_LT(result.completed_spp, 1 << 24);
    EXPECT_GT(result.seconds, 0.5 * budget);
    EXPECT_LT(result.seconds, budget + 0.5 * kTestTimeScale);
    const PixelBounds& crop = scene->film.crop;
    for (int y = crop.y0; y < crop.y1; ++y)
        for (int x = crop.x0; x < crop.x1; ++x)
            ASSERT_GE(result.film->sample_count(x, y), std::uint32_t(result.completed_spp));
    EXPECT_EQ(result.partial, result.max_spp > result.completed_spp);
    std::lock_guard lock(mutex);
    ASSERT_FALSE(reports.empty());
    for (const RenderProgress& p : reports) {
        EXPECT_GE(p.fraction, 0.0);
        EXPECT_LE(p.fraction, 1.0);
        EXPECT_GE(p.elapsed_seconds, 0.0);
    }
}

// The first pass of this scene (51 x 43 pixels in the crop, one tile, so one thread) takes at least
// 2193 x 300 us = 0.66 s of sleeping alone; a 0.1 s budget must stop it part-way instead of letting it run to the
// end. The budget is not scaled for instrumented builds: the pass's length is sleeping, which they do not slow.
// It must not be tiny either: a budget spent before the first pass starts (a few milliseconds can be, on a loaded
// machine) rightly renders nothing, which is not what this test is about.
TEST(TileRenderer, TimeBudgetStopsTheFirstPassWithinASample) {
    const auto scene = load_test_scene(1000, RasterSize{64, 48}, R"({"type": "test_slow_random"})");
    RenderOptions options = options_for(*scene, 64);  // one tile: only a check inside the tile can stop it
    options.time_budget_seconds = 0.1;
    const RenderResult result = render_with_threads(*scene, 2, options);
    EXPECT_TRUE(result.out_of_time);
    EXPECT_FALSE(result.cancelled);
    EXPECT_EQ(result.passes, 1);
    EXPECT_EQ(result.completed_spp, 0);
    EXPECT_EQ(result.max_spp, 1);
    EXPECT_TRUE(result.partial);
    EXPECT_LT(result.film->sample_count_range().total, std::uint64_t(scene->film.crop.area()));
}

ImageBuffer resolve_after(const LoadedScene& scene, const std::string& state, int threads, int tile_size) {
    auto film = std::make_unique<Film>(scene.film);
    film->restore_state(state);
    const RenderResult result = render_with_threads(scene, threads, options_for(scene, tile_size), std::move(film));
    EXPECT_FALSE(result.partial);
    EXPECT_EQ(result.completed_spp, scene.spp);
    return result.film->resolve();
}

// Checkpoints taken every 10 ms land mid-pass (pixels with different sample counts); continuing the render from
// any of them, with other thread counts and tile sizes, gives the uninterrupted image bit for bit.
TEST(TileRenderer, ResumingFromAnyCheckpointIsBitIdentical) {
    const auto scene = load_test_scene(6, RasterSize{16, 12}, R"({"type": "test_slow_random"})");
    const ImageBuffer reference = render_with_threads(*scene, 2, options_for(*scene, 5)).film->resolve();

    RenderOptions options = options_for(*scene, 4);
    options.checkpoint_interval_seconds = 0.01;
    std::vector<std::string> states;
    int partial_states = 0;
    options.on_checkpoint = [&](const Film& film) {
        states.push_back(film.state());
        const SampleCountRange counts = film.sample_count_range();
        partial_states += counts.min != counts.max;
    };
    const RenderResult result = render_with_threads(*scene, 2, options);
    EXPECT_EQ(result.checkpoints, int(states.size()));
    ASSERT_GE(states.size(), 3u);
    EXPECT_GE(partial_states, 1);
    expect_bit_identical(result.film->resolve(), reference, "render with checkpoint pauses");
    for (std::size_t i = 0; i < states.size(); ++i)
        expect_bit_identical(resolve_after(*scene, states[i], 1 + int(i % 2), 3 + int(i % 3)), reference,
                             "resumed from checkpoint " + std::to_string(i));
}

// The same with a real integrator (path tracer) and AOVs, stopped by the time budget at whatever moment it runs out.
TEST(TileRenderer, ResumingAfterATimeBudgetIsBitIdentical) {
    const auto scene = load_test_scene(64, RasterSize{24, 20}, R"({"type": "path", "max_depth": 4})");
    const ImageBuffer reference = render_with_threads(*scene, 2, options_for(*scene, 8)).film->resolve();
    for (double budget : {0.001, 0.01, 0.03}) {
        RenderOptions options = options_for(*scene, 8);
        options.time_budget_seconds = budget;
        const RenderResult stopped = render_with_threads(*scene, 2, options);
        expect_bit_identical(resolve_after(*scene, stopped.film->state(), 2, 7), reference,
                             "resumed after " + std::to_string(budget) + " s");
    }
}

TEST(TileRenderer, HugeTimeBudgetIsNoProblem) {
    SceneOverrides overrides;
    overrides.settings.push_back(spp_setting(6));
    overrides.settings.push_back(resolution_setting(RasterSize{8, 6}));
    const SceneFile file(test_scene());
    const auto scene = load_scene(file.path(), overrides);
    RenderOptions options = options_for(*scene, 4);
    options.time_budget_seconds = 1e30;  // "fits" would overflow an int
    const RenderResult result = render_with_threads(*scene, 2, options);
    EXPECT_EQ(result.completed_spp, 6);
    EXPECT_EQ(result.film->sample_count(4, 3), 6u);
}

TEST(TileRenderer, NonFiniteRadianceIsCountedAndDropped) {
    SceneOverrides overrides;
    overrides.settings.push_back(resolution_setting(RasterSize{16, 12}));
    overrides.settings.push_back(spp_setting(4));
    const SceneFile file(test_scene("", R"({"type": "test_bad_values"})"));
    const auto scene = load_scene(file.path(), overrides);
    const std::uint64_t before = counters::totals().nan_samples;
    g_bad_samples = 0;
    g_huge_samples = 0;
    const RenderResult result = render_with_threads(*scene, 2, options_for(*scene, 5));
    const std::uint64_t bad = g_bad_samples.load();
    EXPECT_GT(bad, 0u);
    EXPECT_GT(g_huge_samples.load(), 0u);
    EXPECT_EQ(counters::totals().nan_samples - before, bad);
    // A finite radiance whose square overflows the film's single-precision sums is dropped too: the sums stay
    // finite, so the film can be checkpointed and resumed.
    EXPECT_NO_THROW(Film(result.film->settings()).restore_state(result.film->state()));
    ImageBuffer image = result.film->resolve();
    const std::size_t stride = image.channels.size();
    int clean = 0, poisoned = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.pixel(x, y);
            for (std::size_t c = 0; c < stride; ++c)
                if (image.channels[c] != "variance.R" && image.channels[c] != "variance.G" &&
                    image.channels[c] != "variance.B" && image.channels[c] != "Z") {
                    ASSERT_TRUE(std::isfinite(p[c])) << image.channels[c] << " at " << x << ", " << y;
                }
            for (const char* variance : {"variance.R", "variance.G", "variance.B"})
                ASSERT_TRUE(std::isfinite(p[channel(image, variance)])) << variance << " at " << x << ", " << y;
            // Left half: every sample was 1. Right half: every sample was dropped to black.
            if (p[0] == 1.0f && p[1] == 1.0f && p[2] == 1.0f) ++clean;
            if (p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f) ++poisoned;
        }
    EXPECT_GE(clean, image.width * image.height / 3);
    EXPECT_GE(poisoned, image.width * image.height / 3);
}

TEST(TileRenderer, DepthAovIsTheViewDepthOfTheFirstHit) {
    // A camera looking straight down -z at a large quad in the plane z = 0 from z = 4: depth 4 everywhere.
    const std::string json = R"({"isotrace": 1,
  "film": {"resolution": [16, 12], "spp": 4, "aovs": ["depth", "position", "normal", "object_id"]},
  "camera": {"type": "perspective", "fov": 60, "look_at": {"eye": [0.5, 0.25, 4], "target": [0.5, 0.25, 0]}},
  "integrator": {"type": "preview", "ambient": 0, "background": 0},
  "materials": {"m": {"type": "diffuse"}},
  "objects": [
    {"material": "m", "shape": {"type": "mesh", "positions": [[-2, -2, 0], [1, -2, 0], [1, 2, 0], [-2, 2, 0]],
     "triangles": [[0, 1, 2], [0, 2, 3]]}}]})";
    const SceneFile file(json);
    const auto scene = load_scene(file.path());
    ImageBuffer image = render_with_threads(*scene, 2, options_for(*scene, 8)).film->resolve();
    const int z = channel(image, "Z"), pz = channel(image, "P.Z"), nz = channel(image, "N.Z"), a = channel(image, "A");
    int hits = 0, misses = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.pixel(x, y);
            if (p[a] == 1.0f) {
                ++hits;
                EXPECT_NEAR(p[z], 4.0f, 1e-5f) << x << ", " << y;
                EXPECT_NEAR(p[pz], 0.0f, 1e-6f);
                EXPECT_EQ(p[nz], 1.0f);
                EXPECT_EQ(p[channel(image, "objectId")], 0.0f);
            } else if (p[a] == 0.0f) {
                ++misses;
                EXPECT_EQ(p[z], std::numeric_limits<float>::infinity());
                EXPECT_EQ(p[channel(image, "objectId")], -1.0f);
            }
        }
    EXPECT_GT(hits, 50);
    EXPECT_GT(misses, 10);  // the quad ends at x = 1, right of the image centre
}

// A material's albedo (its textures evaluated again at every camera hit) is asked for only when the film keeps what
// camera rays hit: not for the beauty alone, nor with only the sample-count and variance AOVs.
TEST(TileRenderer, TheAlbedoIsAskedForOnlyWhenTheFilmKeepsIt) {
    for (const auto& [aovs, kept] : std::vector<std::pair<std::string, float>>{
             {"[]", 0.0f}, {R"(["sample_count", "variance"])", 0.0f}, {R"(["albedo"])", 1.0f}, {R"(["depth"])", 1.0f}}) {
        const SceneFile file(R"({"isotrace": 1, "film": {"resolution": [8, 6], "spp": 2, "aovs": )" + aovs + R"(},
  "camera": {"type": "perspective", "fov": 60, "look_at": {"eye": [0, 0, 4], "target": [0, 0, 0]}},
  "integrator": {"type": "test_albedo_kept"}, "materials": {"m": {"type": "diffuse"}},
  "objects": [{"material": "m", "shape": {"type": "sphere"}}]})");
        const auto scene = load_scene(file.path());
        ImageBuffer image = render_with_threads(*scene, 2, options_for(*scene, 8)).film->resolve();
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) ASSERT_EQ(image.pixel(x, y)[0], kept) << aovs << " at " << x << ", " << y;
    }
}

// stop_at_pass_end is asked at 1, 2, 4, ... spp, once each, with every pixel at that count; the render it stops
// is bit-identical to one with that sample budget, for any thread count and tile size.
TEST(TileRenderer, StopAtPassEndIsAskedAtPowersOfTwoAndStopsThere) {
    const auto scene = load_test_scene(1000, RasterSize{20, 12}, "");
    for (int threads : {1, 2}) {
        std::vector<std::uint32_t> asked;
        RenderOptions options = options_for(*scene, threads == 1 ? 5 : 32);
        options.stop_at_pass_end = [&](const Film& film) {
            const SampleCountRange counts = film.sample_count_range();
            EXPECT_EQ(counts.min, counts.max);
            asked.push_back(counts.min);
            return counts.min >= 16;
        };
        const RenderResult result = render_with_threads(*scene, threads, options);
        EXPECT_EQ(asked, (std::vector<std::uint32_t>{1, 2, 4, 8, 16}));
        EXPECT_TRUE(result.stopped_at_pass_end);
        EXPECT_FALSE(result.out_of_time);
        EXPECT_EQ(result.completed_spp, 16);
        EXPECT_FALSE(result.partial);
        RenderOptions budget = options_for(*scene, 7);
        budget.spp = 16;
        expect_bit_identical(result.film->resolve(), render_with_threads(*scene, 2, budget).film->resolve(),
                             "stopped at 16 spp vs --spp 16");
    }
}

// A film left between boundaries (3 spp, as a time budget can leave it) goes on to 4, then 8, ...: the stop is
// asked at the same counts as in an uninterrupted render.
TEST(TileRenderer, PassesRealignToPowersOfTwoAfterAnOddCount) {
    const auto scene = load_test_scene(1000, RasterSize{8, 8}, "");
    RenderOptions first = options_for(*scene, 8);
    first.spp = 3;
    RenderResult three = render_with_threads(*scene, 1, first);
    ASSERT_EQ(three.completed_spp, 3);
    std::vector<std::uint32_t> asked;
    RenderOptions options = options_for(*scene, 8);
    options.spp = 32;
    options.stop_at_pass_end = recording_pass_ends(asked);
    const RenderResult result = render_with_threads(*scene, 2, options, std::move(three.film));
    EXPECT_EQ(asked, (std::vector<std::uint32_t>{4, 8, 16, 32}));
    EXPECT_EQ(result.passes, 4);
    EXPECT_FALSE(result.stopped_at_pass_end);
}

// A scene whose path tracer traces its samples in groups, packets of eight of them: its passes start at eight samples,
// so that a pixel's first camera rays fill a packet, and then double as before.
TEST(TileRenderer, FirstPassIsAPacketOfEachPixelsSamples) {
    const SceneFile file(R"({"isotrace": 1,
  "film": {"resolution": [12, 10], "spp": 13},
  "camera": {"type": "perspective", "fov": 50, "look_at": {"eye": [0, 1.5, 4], "target": [0, 0, 0]}},
  "integrator": {"type": "path", "max_depth": 3},
  "materials": {"grey": {"type": "diffuse", "reflectance": 0.6}},
  "lights": [{"type": "point", "position": [1, 3, 1], "intensity": 10}],
  "objects": [{"material": "grey", "shape": {"type": "mesh",
    "positions": [[-4, 0, -4], [4, 0, -4], [4, 0, 4], [-4, 0, 4]], "triangles": [[0, 2, 1], [0, 3, 2]]}}]})");
    const auto scene = load_scene(file.path(), {});
    ASSERT_EQ(scene->integrator->samples_traced_together(*scene->scene), Integrator::kMaxSamplesTogether);

    const RenderResult thirteen = render_with_threads(*scene, 2, options_for(*scene, 4));
    EXPECT_EQ(thirteen.completed_spp, 13);
    EXPECT_FALSE(thirteen.partial);
    EXPECT_EQ(thirteen.passes, 2);  // 8, then the 5 left

    std::vector<std::uint32_t> asked;
    RenderOptions options = options_for(*scene, 4);
    options.spp = 32;
    options.stop_at_pass_end = recording_pass_ends(asked);
    const RenderResult result = render_with_threads(*scene, 2, options);
    EXPECT_EQ(asked, (std::vector<std::uint32_t>{8, 16, 32}));
    EXPECT_EQ(result.passes, 3);

    // A film left at 3 samples goes on to 8, then 16: the same boundaries as an uninterrupted render.
    RenderOptions first = options_for(*scene, 4);
    first.spp = 3;
    RenderResult three = render_with_threads(*scene, 1, first);
    ASSERT_EQ(three.completed_spp, 3);
    asked.clear();
    options.spp = 16;
    const RenderResult resumed = render_with_threads(*scene, 2, options, std::move(three.film));
    EXPECT_EQ(asked, (std::vector<std::uint32_t>{8, 16}));
    EXPECT_EQ(resumed.passes, 2);
}

}  // namespace
}  // namespace isotrace
