#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

#include "renderer/colour/chromaticities.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/input_error.h"
#include "renderer/core/render_counters.h"
#include "renderer/core/version.h"
#include "renderer/distributed/render_ranks.h"
#include "renderer/image/image_writer.h"
#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/commands.h"
#include "tools/cli/progress_bar.h"
#include "tools/cli/reference_mode.h"
#include "tools/cli/render_checkpoint.h"
#include "tools/cli/render_distribution.h"
#include "tools/cli/render_pauses.h"
#include "tools/cli/render_statistics.h"
#include "tools/cli/render_warnings.h"
#include "tools/cli/scene_options.h"
#include "tools/cli/thread_limit.h"
#include "tools/cli/memory_limit_option.h"

namespace isotrace::cli {
namespace {

// The first SIGINT or SIGTERM asks the render to stop (it writes what it has, then exits 128 + the signal);
// a second one ends the process at once, removing any half-written output first.
std::atomic<bool> g_interrupted{false};
std::atomic<int> g_first_signal{0};

extern "C" void on_stop_signal(int signal_number) {
    int expected = 0;
    if (g_first_signal.compare_exchange_strong(expected, signal_number)) {
        g_interrupted = true;
        return;
    }
    remove_temporary_files_in_progress();
    ::_exit(128 + signal_number);
}

const char* stop_signal_name(int signal_number) { return signal_number == SIGTERM ? "SIGTERM" : "SIGINT"; }

// Installs on_stop_signal for SIGINT and SIGTERM for its lifetime.
class StopSignals {
public:
    StopSignals() {
        g_interrupted = false;
        g_first_signal = 0;
        struct sigaction action {};
        action.sa_handler = on_stop_signal;
        sigemptyset(&action.sa_mask);
        action.sa_flags = SA_RESTART;
        ::sigaction(SIGINT, &action, &previous_int_);
        ::sigaction(SIGTERM, &action, &previous_term_);
    }
    ~StopSignals() {
        ::sigaction(SIGINT, &previous_int_, nullptr);
        ::sigaction(SIGTERM, &previous_term_, nullptr);
    }
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

private:
    struct sigaction previous_int_ {}, previous_term_ {};
};

struct RenderArguments {
    std::string scene;
    std::vector<std::string> outputs;
    std::optional<int> spp;
    std::string resolution;
    int threads = 0;
    std::string seed;         // parsed by parse_seed: CLI11 would wrap "-1" and clamp 2^64
    std::string aovs;
    std::string stats_json;
    StatisticsDetail stats = StatisticsDetail::Short;
    std::string time_budget;  // parsed by parse_seconds: CLI11 accepts nan
    std::string max_memory;
    std::string max_scene_size;
    int tile_size = 32;
    bool quiet = false;
    std::string checkpoint;
    std::string checkpoint_every;  // parsed by parse_seconds
    std::string write_every;       // parsed by parse_seconds
    std::string resume;
    bool reference = false;
    std::optional<std::string> target_error;  // parsed by parse_reference_request
    DistributionArguments distribution;
    SceneOptions scene_options;
};

constexpr double kDefaultCheckpointSeconds = 300;
// Each checkpoint and interim write pauses the render; the threads need some time between pauses or no sample is
// ever finished.
constexpr double kMinPauseSeconds = 0.05;

// --checkpoint-every and --write-every: seconds, at least kMinPauseSeconds.
double parse_pause_interval(const std::string& text, const std::string& option) {
    const double seconds = parse_seconds(text, option);
    if (seconds < kMinPauseSeconds)
        throw InputError({}, option, "must be at least 0.05 s (the render pauses each time), got \"" + text + "\"");
    return seconds;
}

const char* how_it_ended(const RenderResult& result, int spp) {
    if (result.cancelled) return "interrupted";
    if (result.stopped_at_pass_end) return "target error";
    if (result.completed_spp >= spp) return "complete";
    return "time budget";
}

// `stopped`: how_it_ended(), or "in progress" for an interim output (--write-every).
ImageMetadata make_metadata(const LoadedScene& scene, const RenderResult& result, const std::string& stopped,
                            std::uint64_t rays) {
    ImageMetadata m;
    m.set("Software", std::string("isotrace ") + kIsotraceVersion);
    m.set("isotrace:version", std::string(kIsotraceVersion));
    m.set("isotrace:scene", scene.path);
    m.set("isotrace:spp", std::int64_t(result.completed_spp));
    m.set("isotrace:seed", std::to_string(scene.seed));
    if (!scene.settings.empty()) m.set("isotrace:set", nlohmann::json(scene.settings).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    m.set("isotrace:integrator", scene.integrator_type);
    for (const auto& [key, value] : scene.integrator->settings()) m.set("isotrace:integrator:" + key, value);
    m.set("isotrace:sampler", scene.sampler_type);
    m.set("isotrace:pixel_filter", scene.filter_type);
    m.set("isotrace:render_seconds", result.seconds);
    m.set("isotrace:rays", std::to_string(rays));
    // partial = 1: the render stopped inside a pass, so pixels have between isotrace:spp and isotrace:spp_max
    // samples (each pixel's count is in the sampleCount AOV when requested).
    m.set("isotrace:partial", std::int64_t(result.partial ? 1 : 0));
    m.set("isotrace:spp_max", std::int64_t(result.max_spp));
    m.set("isotrace:stopped", stopped);
    m.set("isotrace:working_space", scene.colours->working_space());
    m.set("isotrace:ocio_config", scene.colours->config_path());
    if (const auto xy = chromaticities_of(scene.colours->working_space()))
        m.set("chromaticities", std::vector<float>(xy->begin(), xy->end()));
    return m;
}

// Every output is attempted even when one fails (a full disk may still take a small PNG); each failure is
// reported, and any failure ends the command with a failure.
void write_outputs(const RenderArguments& args, const LoadedScene& scene, const ImageBuffer& image,
                   const ImageMetadata& metadata) {
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

// What --aov takes: "albedo, normal, ..., or all".
std::string aov_choices() {
    std::string list;
    for (const AovInfo& info : all_aovs()) list += std::string(info.name) + ", ";
    return list + "or all";
}

// The values of --stats, the default first, with what each prints beyond the one before.
struct StatisticsLevel {
    StatisticsDetail detail;
    const char* name;
    const char* prints;  // nullptr: nothing
};
constexpr StatisticsLevel kStatisticsLevels[] = {
    {StatisticsDetail::Short, "short", "default: times, speed, NaNs, memory"},
    {StatisticsDetail::Full, "full", "also rays, geometry and every work counter"},
    {StatisticsDetail::None, "none", nullptr}};

void add_stats_option(CLI::App& command, StatisticsDetail& detail) {
    std::map<std::string, StatisticsDetail> levels;
    std::string help = "Statistics printed after the render:", type_name;
    const std::size_t count = std::size(kStatisticsLevels);
    for (std::size_t i = 0; i < count; ++i) {
        const StatisticsLevel& level = kStatisticsLevels[i];
        levels.emplace(level.name, level.detail);
        help += std::string(i == 0 ? " " : i + 1 == count ? " or " : ", ") + level.name +
                (level.prints ? std::string(" (") + level.prints + ")" : "");
        type_name += std::string(i == 0 ? "" : "|") + level.name;
    }
    command.add_option("--stats", detail, help)
        ->transform(CLI::CheckedTransformer(levels, CLI::ignore_case).description(""))
        ->type_name(type_name);
}

std::vector<std::string> aov_names(const std::vector<Aov>& aovs) {
    std::vector<std::string> names;
    for (Aov aov : aovs) names.push_back(aov_info(aov).name);
    return names;
}

// On --resume, the options that change pixels come from the checkpoint; any given on the command line must match.
void take_pixel_options_from(const ResumePoint& resume, const RenderArguments& args, SceneOverrides& overrides,
                             ReferenceRequest& reference) {
    const PixelOptions& recorded = resume.options;
    const auto mismatch = [&](const std::string& option, const std::string& given, const std::string& kept) {
        throw InputError({args.resume}, "",
                         option + " " + given + " differs from the checkpoint's " + kept +
                             " (options that change pixels cannot change when resuming; leave it out)");
    };
    if (args.spp && *args.spp != recorded.spp)
        mismatch("--spp", std::to_string(*args.spp), std::to_string(recorded.spp));
    if (!args.resolution.empty()) {
        const RasterSize given = parse_resolution(args.resolution, "--res");
        if (given.width != recorded.resolution.width || given.height != recorded.resolution.height)
            mismatch("--res", args.resolution,
                     std::to_string(recorded.resolution.width) + "x" + std::to_string(recorded.resolution.height));
    }
    if (!args.seed.empty() && parse_seed(args.seed, "--seed") != recorded.seed)
        mismatch("--seed", args.seed, std::to_string(recorded.seed));
    std::vector<std::string> given_settings;
    for (const SceneSetting& setting : overrides.settings)
        if (!setting.recorded_apart) given_settings.push_back(setting.text());
    if (!given_settings.empty() && given_settings != recorded.settings) {
        const auto listed = [](const std::vector<std::string>& texts) {
            std::string list;
            for (const std::string& text : texts) list += (list.empty() ? "" : " --set ") + text;
            return list;
        };
        mismatch("--set", listed(given_settings),
                 recorded.settings.empty() ? "(none)" : "--set " + listed(recorded.settings));
    }
    if (args.reference && !recorded.reference)
        throw InputError({args.resume}, "", "--reference: the checkpoint is not of a reference render");
    if (args.target_error && reference.target_error != recorded.target_error)
        mismatch("--target-error", *args.target_error,
                 recorded.target_error ? std::to_string(*recorded.target_error) : "(none)");
    std::vector<Aov> recorded_aovs;
    for (const std::string& name : recorded.extra_aovs) {
        const std::vector<Aov> parsed = parse_aov_list(name, args.resume);
        recorded_aovs.insert(recorded_aovs.end(), parsed.begin(), parsed.end());
    }
    if (!args.aovs.empty() && overrides.extra_aovs != recorded_aovs) {
        std::string kept;
        for (const std::string& name : recorded.extra_aovs) kept += (kept.empty() ? "" : ",") + name;
        mismatch("--aov", args.aovs, kept.empty() ? "(none)" : kept);
    }
    overrides.settings.clear();
    for (const std::string& text : recorded.settings) {
        SceneSetting setting = parse_scene_setting(text);
        setting.create_sections = true;  // it may stand for --view or --display, which create "film"
        overrides.settings.push_back(std::move(setting));
    }
    overrides.settings.push_back(spp_setting(recorded.spp));
    overrides.settings.push_back(resolution_setting(recorded.resolution));
    overrides.settings.push_back(seed_setting(recorded.seed));
    overrides.extra_aovs = recorded_aovs;
    reference = {recorded.reference, recorded.target_error};
}

// Every file the render writes, named by its option.
std::vector<NamedPath> render_outputs(const RenderArguments& args, const std::string& checkpoint_path) {
    std::vector<NamedPath> outputs;
    for (const std::string& output : args.outputs) outputs.push_back({output, "--output"});
    if (!args.stats_json.empty()) outputs.push_back({args.stats_json, "--stats-json", true});
    if (!checkpoint_path.empty()) outputs.push_back({checkpoint_path, "--checkpoint"});
    return outputs;
}

// The inputs named on the command line. The checkpoint being resumed is one, unless the render goes on
// checkpointing to it: it is read whole before the first checkpoint replaces it.
std::vector<NamedPath> command_line_inputs(const RenderArguments& args, const std::string& checkpoint_path) {
    std::vector<NamedPath> inputs{{args.scene, "the scene"}};
    if (!args.resume.empty() && !same_file(args.resume, checkpoint_path))
        inputs.push_back({args.resume, "the checkpoint resumed (--resume)"});
    return inputs;
}

int run_render(const RenderArguments& args) {
    ReferenceRequest reference = parse_reference_request(args.reference, args.target_error, !args.resume.empty());
    SceneOverrides overrides;
    add_scene_settings(args.scene_options, overrides);
    // The shortcuts after --set: "--set film.spp=4 --spp 8" renders 8 samples.
    if (args.spp) overrides.settings.push_back(spp_setting(*args.spp));
    if (!args.resolution.empty()) overrides.settings.push_back(resolution_setting(parse_resolution(args.resolution, "--res")));
    if (!args.seed.empty()) overrides.settings.push_back(seed_setting(parse_seed(args.seed, "--seed")));
    const std::optional<double> time_budget =
        args.time_budget.empty() ? std::nullopt : std::optional<double>(parse_seconds(args.time_budget, "--time"));
    overrides.max_memory_bytes = max_memory_bytes(args.max_memory);
    if (!args.max_scene_size.empty())
        overrides.max_scene_file_bytes = parse_memory_size(args.max_scene_size, "--max-scene-size");
    if (!args.aovs.empty()) overrides.extra_aovs = parse_aov_list(args.aovs, "--aov");
    if (reference.enabled) add_reference_channels(overrides.extra_aovs);
    // A resumed render goes on checkpointing to the file it came from unless told otherwise.
    const std::string checkpoint_path = !args.checkpoint.empty() ? args.checkpoint : args.resume;
    if (!args.checkpoint_every.empty() && checkpoint_path.empty())
        throw InputError({}, "--checkpoint-every", "needs --checkpoint FILE (or --resume FILE)");
    const double checkpoint_seconds = args.checkpoint_every.empty()
                                          ? kDefaultCheckpointSeconds
                                          : parse_pause_interval(args.checkpoint_every, "--checkpoint-every");
    const std::optional<double> write_seconds =
        args.write_every.empty() ? std::nullopt
                                 : std::optional<double>(parse_pause_interval(args.write_every, "--write-every"));
    for (const std::string& output : args.outputs) image_kind_for(output);  // reject bad names before rendering
    const std::vector<NamedPath> outputs = render_outputs(args, checkpoint_path);
    check_output_paths(outputs, command_line_inputs(args, checkpoint_path));
    std::optional<ResumePoint> resume;
    if (!args.resume.empty()) {
        resume = read_resume_point(args.resume);
        take_pixel_options_from(*resume, args, overrides, reference);
    }
    if (reference.enabled) require_reference_output(args.outputs);

    const ThreadLimit limit(args.threads);
    const int threads = limit.threads();

    counters::reset();
    const auto load_start = std::chrono::steady_clock::now();
    RenderRanks ranks("render");  // one of several when started by mpirun or srun (docs/distributed.md)
    if (ranks.leave_quietly()) return kExitOk;
    std::unique_ptr<LoadedScene> scene = ranks.load_scene(args.scene, overrides);
    // This rank may not take part (rank 0 refused the run). Rank 0 says why and exits with 2, which becomes the job's
    // status; a worker that left with 2 first made the launcher kill rank 0 before its message was out (a flaky
    // mpi_bad_input), so the worker leaves quietly.
    if (!scene) return kExitOk;
    std::vector<NamedPath> inputs = command_line_inputs(args, checkpoint_path);
    for (NamedPath& input : scene_inputs(*scene)) inputs.push_back(std::move(input));
    check_output_paths(outputs, inputs);  // the files the scene names are known now
    if (reference.enabled) scene->film.half_float = false;  // a reference keeps every bit of its mean and variance
    if (!ranks.coordinator()) {
        ranks.serve(*scene, args.tile_size);
        return kExitOk;
    }
    // A distributed render's stop by a signal ends in one last on_checkpoint call, which must be the checkpoint.
    if (write_seconds && ranks.distributed())
        throw InputError({}, "--write-every", "is not available in a distributed render; render in one process to "
                                              "watch the image grow");
    std::unique_ptr<Film> film;
    if (resume) {
        check_same_scene(*resume, *scene, args.resume);
        film = std::make_unique<Film>(scene->film);
        try {
            film->restore_state(resume->film_state, std::uint32_t(resume->options.spp));
        } catch (const std::invalid_argument& error) {
            throw InputError({args.resume}, "", std::string("the checkpoint does not fit this film: ") + error.what());
        }
        std::string().swap(resume->film_state);  // as large as the film it now lives in: not kept for the render
    }
    PhaseTimes times;
    times.parse = scene->parse_seconds;
    times.build = scene->scene->build_statistics().seconds;

    RenderOptions options;
    options.tile_size = args.tile_size;
    // --time or --target-error alone lifts the sample limit; with --spp too, whichever ends first ends the render.
    const bool lifted = (time_budget || reference.target_error) && !args.spp;
    options.spp = resume ? resume->options.spp : lifted ? kMaxSamplesPerPixel : scene->spp;
    options.time_budget_seconds = time_budget;
    options.cancel = &g_interrupted;
    const PixelOptions pixel_options{options.spp,       scene->film.raster,       scene->seed,
                                     aov_names(overrides.extra_aovs), reference.enabled, reference.target_error,
                                     scene->settings};
    if (reference.enabled) options.stop_at_pass_end = reference_stop_rule(reference, args.quiet);
    // False when it could not be written; the render goes on, and the next checkpoint may succeed.
    const auto checkpoint = [&](const Film& state) {
        try {
            save_checkpoint(checkpoint_path, *scene, pixel_options, state);
            return true;
        } catch (const std::runtime_error& error) {
            std::fprintf(stderr, "isotrace: warning: no checkpoint written: %s\n", error.what());
            return false;
        }
    };
    const auto render_start = std::chrono::steady_clock::now();
    // The outputs as they stand, for a viewer to watch; a failed write is reported and the render goes on.
    const auto write_interim_outputs = [&](const Film& state) {
        const SampleCountRange counts = state.sample_count_range();
        RenderResult so_far;
        so_far.completed_spp = int(counts.min);
        so_far.max_spp = int(counts.max);
        so_far.partial = counts.min != counts.max;
        so_far.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - render_start).count();
        try {
            write_outputs(args, *scene, state.resolve(),
                          make_metadata(*scene, so_far, "in progress", counters::totals().total_rays()));
        } catch (const std::runtime_error& error) {
            std::fprintf(stderr, "isotrace: warning: interim outputs not written: %s\n", error.what());
        }
    };
    RenderPauses pauses;
    if (!checkpoint_path.empty()) pauses.add(checkpoint_seconds, [&](const Film& state) { checkpoint(state); });
    if (write_seconds) pauses.add(*write_seconds, write_interim_outputs);
    pauses.install(options);

    if (!args.quiet) {
        const SampleCountRange done = film ? film->sample_count_range() : SampleCountRange{};
        std::fprintf(stderr, "isotrace: %s: %dx%d, %s, %s integrator, %d thread(s), loaded in %.2f s%s\n",
                     args.scene.c_str(), scene->film.raster.width, scene->film.raster.height,
                     options.spp == kMaxSamplesPerPixel ? "no sample limit" : (std::to_string(options.spp) + " spp").c_str(),
                     scene->integrator_type.c_str(), threads,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count(),
                     resume ? (", resuming at " + std::to_string(done.min) + " spp").c_str() : "");
    }
    // Warnings print even with --quiet: they say that the image is not what was asked for.
    if (const std::string warning = light_left_out_warning(*scene); !warning.empty())
        std::fprintf(stderr, "isotrace: warning: %s\n", warning.c_str());

    // A reference render prints its error estimate at each pass boundary instead of drawing the bar.
    const bool show_progress = !args.quiet && stderr_is_terminal() && !reference.enabled;
    ProgressBar bar(show_progress);
    if (show_progress) options.on_progress = [&](const RenderProgress& p) { bar.update(p); };
    else if (ranks.distributed() && !args.quiet) options.on_progress = progress_lines(10);
    const StopSignals signals;  // until the outputs are written: a second signal then removes the temporary file
    // The image module loads while the render runs (not before: the render's threads would wait for it to start).
    // A module that cannot be loaded stops the render, and writing the images then fails with the loader's reason.
    std::optional<ImageCodecPreload> image_module;
    if (!args.outputs.empty())
        options.on_started = [&] {
            image_module.emplace(std::vector<std::filesystem::path>(args.outputs.begin(), args.outputs.end()),
                                 [] { g_interrupted = true; });
        };
    const RenderResult result = ranks.render(*scene, options, std::move(film), work_split(args.distribution));
    // The load has nothing left to overlap: wait for it here rather than at the end of the scope, so that a second
    // signal during the write (_exit from the handler) finds no finished thread unjoined (ThreadSanitizer reports
    // one as a leak; cli_second_signal under `tools/test --sanitize thread`).
    image_module.reset();
    bar.finish();
    times.render = result.seconds;
    // Writing a large film takes a while: say that the signal was heard, and what a second one does.
    if (const int signal_number = g_first_signal.load())
        std::fprintf(stderr, "isotrace: %s: stopped; writing what was rendered (a second signal ends at once)\n",
                     stop_signal_name(signal_number));

    const CounterTotals counts = ranks.counter_totals();
    const auto write_start = std::chrono::steady_clock::now();
    // An unfinished render leaves a checkpoint to continue from.
    const bool unfinished = result.completed_spp < options.spp && !result.stopped_at_pass_end;
    const bool checkpoint_lost = !checkpoint_path.empty() && unfinished && !checkpoint(*result.film);
    ImageMetadata metadata = make_metadata(*scene, result, how_it_ended(result, options.spp), counts.total_rays());
    if (reference.enabled)
        add_reference_metadata(metadata, reference, {scene->film.raster, scene->seed, options.spp, time_budget}, *scene,
                               result);
    const ImageBuffer image = result.film->resolve();
    write_outputs(args, *scene, image, metadata);
    times.write = std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count();

    const BeautyCheck beauty = check_beauty(image);
    nlohmann::json stats = render_statistics(*scene, result, counts, times, threads, beauty);
    add_rank_statistics(stats, ranks);
    if (!args.stats_json.empty()) write_text_output(args.stats_json, stats.dump(2) + "\n");
    for (const std::string& warning : beauty_warnings(beauty))
        std::fprintf(stderr, "isotrace: warning: %s\n", warning.c_str());
    const std::string unmet_target = unmet_target_warning(reference, result);
    if (!unmet_target.empty()) std::fprintf(stderr, "isotrace: warning: %s\n", unmet_target.c_str());
    if (!args.quiet) {
        std::fputs(format_statistics(stats, args.stats).c_str(), stderr);
        for (const std::string& output : args.outputs) std::fprintf(stderr, "wrote %s\n", output.c_str());
        if (!checkpoint_path.empty() && unfinished && !checkpoint_lost)
            std::fprintf(stderr, "wrote checkpoint %s (continue with --resume %s)\n", checkpoint_path.c_str(),
                         checkpoint_path.c_str());
    }
    // The images are written, but the render cannot be continued: an output is missing.
    if (checkpoint_lost) {
        std::fprintf(stderr, "isotrace: failure: the render is unfinished and its checkpoint %s could not be written\n",
                     checkpoint_path.c_str());
        return kExitFailure;
    }
    if (const int signal_number = g_first_signal.load()) {
        std::fprintf(stderr, "isotrace: interrupted by %s: wrote the %s image rendered so far\n",
                     stop_signal_name(signal_number), result.partial ? "partial" : "completed-pass");
        return 128 + signal_number;
    }
    return unmet_target.empty() ? kExitOk : kExitNotMet;
}

}  // namespace

CommandRunner add_render_options(CLI::App* command) {
    auto args = std::make_shared<RenderArguments>();
    command->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
    command->add_option("-o,--output", args->outputs,
                        "Output image; repeat for several. .exr: scene-linear with AOVs and metadata; "
                        ".png/.jpg/.tif: display-referred through the OCIO view. Default: <scene name>.exr")
        ->type_name("PATH");
    command->add_option("--spp", args->spp, "Samples per pixel (sets film.spp)")->check(CLI::Range(1, kMaxSamplesPerPixel));
    command->add_option("--res", args->resolution,
                        "Resolution WIDTHxHEIGHT, each side 1 to 65536 (sets film.resolution)")
        ->type_name("WIDTHxHEIGHT");
    add_threads_option(*command, args->threads);
    command->add_option("--seed", args->seed, "Sampler seed, 0 to 2^64 - 1 (sets sampler.seed)")->type_name("UINT64");
    command->add_option("--aov", args->aovs, "Comma-separated AOVs to add to the EXR: " + aov_choices())
        ->type_name("LIST");
    command->add_option("--stats-json", args->stats_json,
                        "Write every end-of-render statistic as JSON to this file (- for standard output)")
        ->type_name("PATH");
    add_stats_option(*command, args->stats);
    command->add_option("--time", args->time_budget,
                        "Time budget in seconds: the render stops within a sample of it, mid-pass if need be "
                        "(the image is then marked partial)")
        ->type_name("SECONDS>0");
    command->add_option("--checkpoint", args->checkpoint,
                        "Save the render's state to this file periodically, when interrupted (SIGINT, SIGTERM) and "
                        "when the time budget ends it")
        ->type_name("PATH");
    command->add_option("--checkpoint-every", args->checkpoint_every,
                        "Seconds of rendering between checkpoints (default: 300)")
        ->type_name("SECONDS>=0.05");
    command->add_option("--write-every", args->write_every,
                        "Also write the outputs every this many seconds of rendering (atomically, marked "
                        "isotrace:stopped \"in progress\"), so that a viewer can watch the render")
        ->type_name("SECONDS>=0.05");
    command->add_option("--resume", args->resume,
                        "Continue the render saved in this checkpoint (same scene; the final image is bit-identical "
                        "to an uninterrupted render); goes on checkpointing to it unless --checkpoint says otherwise")
        ->type_name("PATH")
        ->check(CLI::ExistingFile);
    add_reference_options(*command, args->reference, args->target_error);
    add_max_memory_option(*command, args->max_memory);
    command->add_option("--max-scene-size", args->max_scene_size,
                        "Refuse scene files larger than this (bytes with K/M/G; default: 64M)")
        ->type_name("SIZE");
    command->add_option("--tile-size", args->tile_size, "Tile edge in pixels (does not change the image)")
        ->check(CLI::Range(1, 4096));
    command->add_flag("-q,--quiet", args->quiet,
                      "No progress bar or statistics on stderr (warnings and errors still print)");
    add_distribution_options(*command, args->distribution);
    add_scene_options(*command, args->scene_options, DisplayOptions::Yes);
    return [args] {
        if (args->outputs.empty())
            args->outputs.push_back(std::filesystem::path(args->scene).stem().string() + ".exr");
        return run_render(*args);
    };
}

}  // namespace isotrace::cli
