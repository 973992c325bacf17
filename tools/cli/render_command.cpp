#include <csignal>
#include <cstdio>
#include <filesystem>

#include "renderer/colour/chromaticities.h"
#include "renderer/core/input_error.h"
#include "renderer/core/render_counters.h"
#include "renderer/core/version.h"
#include "renderer/image/image_writer.h"
#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/commands.h"
#include "tools/cli/progress_bar.h"
#include "tools/cli/render_statistics.h"
#include "tools/cli/thread_limit.h"

namespace isotrace::cli {
namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void on_interrupt(int) {
    g_interrupted = true;
    std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C ends the process at once
}

struct RenderArguments {
    std::string scene;
    std::vector<std::string> outputs;
    std::optional<int> spp;
    std::string resolution;
    int threads = 0;
    std::string seed;         // parsed by parse_seed: CLI11 would wrap "-1" and clamp 2^64
    std::string aovs;
    std::string stats_json;
    std::string time_budget;  // parsed by parse_seconds: CLI11 accepts nan
    std::string max_memory;
    std::string max_scene_size;
    int tile_size = 32;
    bool quiet = false;
};

ImageMetadata make_metadata(const LoadedScene& scene, const RenderResult& result, std::uint64_t rays) {
    ImageMetadata m;
    m.set("Software", std::string("isotrace ") + kIsotraceVersion);
    m.set("isotrace:version", std::string(kIsotraceVersion));
    m.set("isotrace:scene", scene.path);
    m.set("isotrace:spp", std::int64_t(result.completed_spp));
    m.set("isotrace:seed", std::to_string(scene.seed));
    m.set("isotrace:integrator", scene.integrator_type);
    for (const auto& [key, value] : scene.integrator->settings()) m.set("isotrace:integrator:" + key, value);
    m.set("isotrace:sampler", scene.sampler_type);
    m.set("isotrace:pixel_filter", scene.filter_type);
    m.set("isotrace:render_seconds", result.seconds);
    m.set("isotrace:rays", std::to_string(rays));
    m.set("isotrace:partial", std::int64_t(result.partial ? 1 : 0));
    m.set("isotrace:working_space", scene.colours->working_space());
    m.set("isotrace:ocio_config", scene.colours->config_path());
    if (const auto xy = chromaticities_of(scene.colours->working_space()))
        m.set("chromaticities", std::vector<float>(xy->begin(), xy->end()));
    return m;
}

// Every output is attempted even when one fails (a full disk may still take a small PNG); each failure is
// reported, and any failure ends the command with a failure.
void write_outputs(const RenderArguments& args, const LoadedScene& scene, const RenderResult& result,
                   std::uint64_t rays) {
    const ImageBuffer image = result.film->resolve();
    const ImageMetadata metadata = make_metadata(scene, result, rays);
    const ImageWindow window{scene.film.raster, scene.film.crop.x0, scene.film.crop.y0};
    int failures = 0;
    for (const std::string& output : args.outputs) {
        try {
            if (image_kind_for(output) == ImageKind::Exr)
                write_exr(output, image, window, scene.film.half_float, metadata);
            else
                write_display_image(output, image, *scene.colours, scene.display, scene.view, metadata);
        } catch (const std::runtime_error& error) {
            std::fprintf(stderr, "isotrace: failure: %s\n", error.what());
            ++failures;
        }
    }
    if (failures > 0)
        throw std::runtime_error(std::to_string(failures) + " of " + std::to_string(args.outputs.size()) +
                                 " output(s) could not be written");
}

int run_render(const RenderArguments& args) {
    const bool show_progress = !args.quiet && stderr_is_terminal();
    SceneOverrides overrides;
    overrides.spp = args.spp;
    if (!args.seed.empty()) overrides.seed = parse_seed(args.seed, "--seed");
    const std::optional<double> time_budget =
        args.time_budget.empty() ? std::nullopt : std::optional<double>(parse_seconds(args.time_budget, "--time"));
    if (!args.max_memory.empty()) overrides.max_memory_bytes = parse_memory_size(args.max_memory, "--max-memory");
    if (!args.max_scene_size.empty())
        overrides.max_scene_file_bytes = parse_memory_size(args.max_scene_size, "--max-scene-size");
    if (!args.resolution.empty()) overrides.resolution = parse_resolution(args.resolution, "--res");
    if (!args.aovs.empty()) overrides.extra_aovs = parse_aov_list(args.aovs, "--aov");
    for (const std::string& output : args.outputs) {  // reject bad names before rendering
        image_kind_for(output);
        check_output_directory(output, "--output");
    }
    if (!args.stats_json.empty()) check_output_directory(args.stats_json, "--stats-json");
    if (!args.outputs.empty()) image_codec();  // a missing image module fails now, not after the render

    const ThreadLimit limit(args.threads);
    const int threads = limit.threads();

    counters::reset();
    const auto load_start = std::chrono::steady_clock::now();
    std::unique_ptr<LoadedScene> scene = load_scene(args.scene, overrides);
    PhaseTimes times;
    times.parse = scene->parse_seconds;
    times.build = scene->scene->build_statistics().seconds;
    if (!args.quiet)
        std::fprintf(stderr, "isotrace: %s: %dx%d, %d spp, %s integrator, %d thread(s), loaded in %.2f s\n",
                     args.scene.c_str(), scene->film.raster.width, scene->film.raster.height,
                     time_budget && !args.spp ? 0 : scene->spp, scene->integrator_type.c_str(), threads,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count());

    ProgressBar bar(show_progress);
    RenderOptions options;
    options.tile_size = args.tile_size;
    // --time alone lifts the sample limit; with --spp too, whichever budget runs out first ends the render.
    options.spp = time_budget && !args.spp ? (1 << 24) : scene->spp;
    options.time_budget_seconds = time_budget;
    options.cancel = &g_interrupted;
    if (show_progress) options.on_progress = [&](const RenderProgress& p) { bar.update(p); };
    g_interrupted = false;
    std::signal(SIGINT, on_interrupt);
    const RenderResult result = render_scene(*scene, options);
    std::signal(SIGINT, SIG_DFL);
    bar.finish();
    times.render = result.seconds;

    const CounterTotals counts = counters::totals();
    const auto write_start = std::chrono::steady_clock::now();
    write_outputs(args, *scene, result, counts.total_rays());
    times.write = std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count();

    const nlohmann::json stats = render_statistics(*scene, result, counts, times, threads);
    if (!args.stats_json.empty()) write_text_atomically(args.stats_json, stats.dump(2) + "\n");
    if (!args.quiet) {
        std::fputs(format_statistics(stats).c_str(), stderr);
        for (const std::string& output : args.outputs) std::fprintf(stderr, "wrote %s\n", output.c_str());
    }
    if (result.cancelled) {
        std::fprintf(stderr, "isotrace: interrupted: wrote the %s image rendered so far\n",
                     result.partial ? "partial" : "completed-pass");
        return kExitInterrupted;
    }
    return kExitOk;
}

}  // namespace

CommandRunner add_render_command(CLI::App& app) {
    auto args = std::make_shared<RenderArguments>();
    CLI::App* command = app.add_subcommand("render", "Render a scene to image files");
    command->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
    command->add_option("-o,--output", args->outputs,
                        "Output image; repeat for several. .exr: scene-linear with AOVs and metadata; "
                        ".png/.jpg/.tif: display-referred through the OCIO view. Default: <scene name>.exr");
    command->add_option("--spp", args->spp, "Samples per pixel (overrides the scene)")->check(CLI::Range(1, 1 << 24));
    command->add_option("--res", args->resolution, "Resolution WIDTHxHEIGHT (overrides the scene)");
    add_threads_option(*command, args->threads);
    command->add_option("--seed", args->seed, "Sampler seed, 0 to 2^64 - 1 (overrides the scene)");
    command->add_option("--aov", args->aovs,
                        "Comma-separated AOVs to add to the EXR: albedo, normal, depth, position, object_id, "
                        "primitive_id, sample_count, variance, or all");
    command->add_option("--stats-json", args->stats_json, "Write end-of-render statistics as JSON to this file");
    command->add_option("--time", args->time_budget,
                        "Time budget in seconds (progressive passes; stops after the pass that reaches it)");
    command->add_option("--max-memory", args->max_memory,
                        "Refuse scenes whose estimated memory exceeds this: bytes with K/M/G/T, or a percentage of "
                        "physical memory (default: 80%)");
    command->add_option("--max-scene-size", args->max_scene_size,
                        "Refuse scene files larger than this (bytes with K/M/G; default: 64M)");
    command->add_option("--tile-size", args->tile_size, "Tile edge in pixels (does not change the image)")
        ->check(CLI::Range(1, 4096));
    command->add_flag("-q,--quiet", args->quiet, "No progress bar or statistics on stderr");
    return [args] {
        if (args->outputs.empty())
            args->outputs.push_back(std::filesystem::path(args->scene).stem().string() + ".exr");
        return run_render(*args);
    };
}

}  // namespace isotrace::cli
