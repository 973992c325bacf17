// isotrace bench: the benchmark suite (tools/cli/bench_workloads.h), the element-count scaling
// (tools/cli/bench_scaling.h) and the blob direct-vs-tessellated comparison (docs/benchmarks.md)
// (tools/cli/blob_benchmark.h), reported as a table, JSON and a self-contained HTML page.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <thread>

#include "renderer/core/input_error.h"
#include "renderer/distributed/render_ranks.h"
#include "tools/cli/bench_html_report.h"
#include "tools/cli/bench_ranks.h"
#include "tools/cli/bench_report.h"
#include "tools/cli/bench_suite_report.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/commands.h"
#include "tools/cli/machine_description.h"
#include "tools/cli/object_field.h"
#include "tools/cli/progress_bar.h"

namespace isotrace::cli {
namespace {

// The report's format version: 2 is the suite (version 1, the blob comparison alone, is now "blob_comparison").
constexpr int kBenchReportVersion = 2;

struct BenchArguments {
    std::vector<std::string> scenes;  // of the blob comparison; default below
    std::vector<int> threads;         // default: all cores
    int repeats = 3;
    double min_run_time = 0;
    std::string resolution = "320x180";
    std::string filter = ".";
    bool quick = false;
    bool list = false;
    bool scaling = false;
    std::size_t scaling_max = 1'000'000;
    TessellationOptions tessellation;
    std::string json, report;
    bool quiet = false;
    // Whether the user set the values --quick would otherwise lower.
    const CLI::Option *repeats_option = nullptr, *resolution_option = nullptr, *scaling_max_option = nullptr;
};

// std::regex compiles by recursion and matches by backtracking: a long or deeply nested pattern could overflow the
// stack or run for hours. Workload names are short, so short, shallow patterns lose nothing.
constexpr std::size_t kMaxFilterLength = 256;
constexpr int kMaxFilterNesting = 8;

std::regex filter_regex(const std::string& filter) {
    if (filter.size() > kMaxFilterLength)
        throw InputError({}, "--filter", "the pattern is longer than " + std::to_string(kMaxFilterLength) + " characters");
    int depth = 0;
    for (std::size_t i = 0; i < filter.size(); ++i) {
        if (filter[i] == '\\') ++i;  // an escaped character is not a group
        else if (filter[i] == '(' && ++depth > kMaxFilterNesting)
            throw InputError({}, "--filter",
                             "the pattern nests groups deeper than " + std::to_string(kMaxFilterNesting) + " levels");
        else if (filter[i] == ')') --depth;
    }
    try {
        return std::regex(filter, std::regex::ECMAScript);
    } catch (const std::regex_error& error) {
        throw InputError({}, "--filter", "\"" + filter + "\" is not a valid regular expression: " + error.what());
    }
}

std::vector<std::string> names_of(const std::vector<Workload>& workloads) {
    std::vector<std::string> names;
    for (const Workload& w : workloads) names.push_back(w.name);
    return names;
}

nlohmann::json settings_json(const BenchArguments& args, const SuiteSettings& suite) {
    nlohmann::json settings = {{"threads", suite.threads},
                               {"repeats", suite.repeats},
                               {"min_run_seconds", suite.min_run_seconds},
                               {"warm_up_runs", kWarmUpRuns},
                               {"quick", args.quick},
                               {"filter", args.filter},
                               {"path_spp", suite.path_spp},
                               {"mesh_depth", suite.mesh_depth}};
    settings["resolution"] = suite.resolution
                                 ? nlohmann::json::array({suite.resolution->width, suite.resolution->height})
                                 : nlohmann::json();
    return settings;
}

int run_bench(BenchArguments args) {
    const std::vector<Workload> all = suite_workloads();
    if (args.list) {
        for (const Workload& w : all) std::printf("%s\n", w.name.c_str());
        return kExitOk;
    }
    const std::vector<Workload> selected = workloads_matching(all, filter_regex(args.filter));
    if (selected.empty() && !args.scaling)
        throw InputError({}, "--filter",
                         "\"" + args.filter + "\" matches no workload; workloads: " + joined_names(names_of(all)));
    std::vector<NamedPath> outputs;
    if (!args.json.empty()) outputs.push_back({args.json, "--json"});
    if (!args.report.empty()) outputs.push_back({args.report, "--report"});
    check_output_paths(outputs, {});

    if (args.quick) {  // the whole suite in well under a minute on 2 cores
        if (args.repeats_option->count() == 0) args.repeats = 1;
        if (args.resolution_option->count() == 0) args.resolution = "160x90";
        if (args.scaling_max_option->count() == 0) args.scaling_max = 100'000;
    }
    SuiteSettings suite;
    suite.threads = args.threads.empty() ? std::vector<int>{int(std::max(1u, std::thread::hardware_concurrency()))}
                                         : args.threads;
    std::sort(suite.threads.begin(), suite.threads.end());
    suite.threads.erase(std::unique(suite.threads.begin(), suite.threads.end()), suite.threads.end());
    suite.repeats = args.repeats;
    suite.min_run_seconds = args.min_run_time;
    if (args.resolution != "scene") suite.resolution = parse_resolution(args.resolution, "--resolution");
    suite.path_spp = args.quick ? 1 : 4;
    suite.mesh_depth = args.quick ? 6 : 8;

    const bool run_comparison = std::any_of(selected.begin(), selected.end(), [](const Workload& w) {
        return w.kind == WorkloadKind::BlobComparison;
    });
    BlobBenchmarkSettings comparison;
    if (run_comparison) {
        comparison.scenes = !args.scenes.empty() ? args.scenes
                            : args.quick        ? std::vector<std::string>{"scenes/blobs_1k.json", "scenes/blobs_10k.json"}
                                                : std::vector<std::string>{"scenes/blobs_1k.json", "scenes/blobs_10k.json",
                                                                           "scenes/blobs_100k.json"};
        for (const std::string& scene : comparison.scenes)
            if (!std::filesystem::is_regular_file(scene))
                throw InputError({}, "scene",
                                 "\"" + scene + "\" does not exist (run from the source tree or name the scenes)");
        comparison.threads = suite.threads;
        comparison.repeats = suite.repeats;
        comparison.min_run_seconds = suite.min_run_seconds;
        comparison.resolution = suite.resolution;
        comparison.tessellation = args.tessellation;
    }

    const bool show_progress = !args.quiet && stderr_is_terminal();
    const auto log = [show_progress](const std::string& line) {
        if (show_progress) std::fprintf(stderr, "bench: %s\n", line.c_str());
    };
    nlohmann::json report = {{"isotrace_bench", kBenchReportVersion},
                             {"machine", machine_description()},
                             {"settings", settings_json(args, suite)},
                             {"workloads", nlohmann::json::array()},
                             {"scaling", nullptr},
                             {"blob_comparison", nullptr}};
    // Under mpirun or srun every rank runs the workloads at the same time: rank 0 reports their sum (and runs the
    // scaling and blob comparison alone).
    RenderRanks ranks("bench");
    if (ranks.leave_quietly()) return kExitOk;
    for (const WorkloadResult& result : run_workloads(selected, suite, log))
        report["workloads"].push_back(workload_json(result));
    if (ranks.distributed()) {
        const std::vector<std::string> gathered = ranks.gather(report["workloads"].dump());
        if (!ranks.coordinator()) return kExitOk;
        std::vector<nlohmann::json> rank_workloads;
        for (const std::string& workloads : gathered) rank_workloads.push_back(nlohmann::json::parse(workloads));
        report["mpi"] = rank_aggregate(rank_workloads);
    }
    if (args.scaling) {
        const RasterSize resolution = suite.resolution.value_or(RasterSize{320, 180});
        const int threads = suite.threads.back();
        report["scaling"] = {{"threads", threads},
                             {"resolution", {resolution.width, resolution.height}},
                             {"points", scaling_json(run_scaling(scaling_counts(args.scaling_max), resolution, threads,
                                                                 suite.repeats, suite.min_run_seconds, log))}};
    }
    if (run_comparison) report["blob_comparison"] = benchmark_json(comparison, run_blob_benchmark(comparison, log));

    std::fputs(suite_table(report).c_str(), stdout);
    if (report.contains("mpi")) std::fputs(rank_aggregate_table(report["mpi"]).c_str(), stdout);
    if (run_comparison) std::fputs(("\n" + benchmark_table(report["blob_comparison"])).c_str(), stdout);
    if (!args.json.empty()) write_text_output(args.json, report.dump(2) + "\n");
    if (!args.report.empty()) write_text_output(args.report, bench_html_report(report));
    return kExitOk;
}

}  // namespace

CommandRunner add_bench_options(CLI::App* command) {
    auto args = std::make_shared<BenchArguments>();
    command->footer("Primary, shadow and bounce rays, the path tracer and the polygoniser on fixed scenes, with thread "
                    "and element-count scaling. Run from the source tree; --list names the workloads.");
    command->add_option("scenes", args->scenes,
                        "Scene files with blob groups, isosurfaces, superquadrics, CSG solids, tori, cylinders or cones for the "
                        "blobs/direct_vs_tessellated workload (default: "
                        "scenes/blobs_1k, _10k, _100k)");
    command
        ->add_option("--threads", args->threads,
                     "Thread counts to measure, e.g. 1,2 (a thread-scaling table; default: all cores)")
        ->delimiter(',')
        ->check(CLI::Range(1, 4096));
    args->repeats_option = command->add_option("--repeats", args->repeats, "Timed runs per measurement, after one warm-up run")
                               ->capture_default_str()
                               ->check(CLI::Range(1, 1000));
    command
        ->add_option("--min-run-time", args->min_run_time,
                     "Seconds a timed run lasts at least: a shorter one repeats its work and counts the time per pass "
                     "(0: one pass). Repeating the same rays keeps their part of the scene in the caches, as a long "
                     "render does; one pass of a few thousand rays after another scene's turn starts from cold caches")
        ->type_name("SECONDS")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 60.0));
    args->resolution_option =
        command->add_option("--resolution", args->resolution, "WIDTHxHEIGHT of the ray grid and image, or \"scene\"")
            ->type_name("WIDTHxHEIGHT|scene")
            ->capture_default_str();
    command->add_option("--filter", args->filter, "Run only the workloads whose names match this regular expression")
        ->type_name("REGEX")
        ->capture_default_str();
    command->add_flag("--quick", args->quick,
                      "1 run after the warm-up, 160x90, 1 spp, smaller blob scenes: the suite in under a minute");
    command->add_flag("--list", args->list, "List the workload names and exit");
    command->add_flag("--scaling", args->scaling,
                      "Also measure the cost per ray and bytes per element of generated blob groups, 1k to "
                      "--scaling-max elements at a fixed density");
    args->scaling_max_option =
        command->add_option("--scaling-max", args->scaling_max, "Largest element count of --scaling (--quick: 100000)")
            ->capture_default_str()
            ->check(CLI::Range(std::size_t(1000), std::size_t(100'000'000)));
    args->tessellation.add_to(*command);
    command->add_option("--json", args->json, "Also write the results as JSON to this file")->type_name("PATH");
    command->add_option("--report", args->report, "Also write an HTML page with the results as plots to this file")
        ->type_name("PATH");
    command->add_flag("-q,--quiet", args->quiet, "No progress lines on stderr");
    return [args] { return run_bench(*args); };
}

}  // namespace isotrace::cli
