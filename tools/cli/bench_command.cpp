// isotrace bench: the blob-group benchmark of issues 4 and 9 (see tools/cli/blob_benchmark.h).
#include <cstdio>
#include <filesystem>

#include "renderer/core/input_error.h"
#include "tools/cli/bench_report.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/commands.h"
#include "tools/cli/progress_bar.h"

namespace isotrace::cli {
namespace {

struct BenchArguments {
    std::vector<std::string> scenes = {"scenes/blobs_1k.json", "scenes/blobs_10k.json", "scenes/blobs_100k.json"};
    std::vector<int> threads = {1, 2};
    int repeats = 3;
    std::string resolution = "320x180";
    TessellationOptions tessellation;
    std::string json;
    bool quiet = false;
};

int run_bench(const BenchArguments& args) {
    BlobBenchmarkSettings settings;
    for (const std::string& scene : args.scenes)
        if (!std::filesystem::is_regular_file(scene))
            throw InputError({}, "scene", "\"" + scene + "\" does not exist (run from the source tree or name the scenes)");
    settings.scenes = args.scenes;
    settings.threads = args.threads;
    settings.repeats = args.repeats;
    if (args.resolution != "scene") settings.resolution = parse_resolution(args.resolution, "--resolution");
    settings.tessellation = args.tessellation;
    if (!args.json.empty()) check_output_directory(args.json, "--json");

    const bool show_progress = !args.quiet && stderr_is_terminal();
    const auto log = [show_progress](const std::string& line) {
        if (show_progress) std::fprintf(stderr, "bench: %s\n", line.c_str());
    };
    const nlohmann::json report = benchmark_json(settings, run_blob_benchmark(settings, log));
    std::fputs(benchmark_table(report).c_str(), stdout);
    if (!args.json.empty()) write_text_atomically(args.json, report.dump(2) + "\n");
    return kExitOk;
}

}  // namespace

CommandRunner add_bench_command(CLI::App& app) {
    auto args = std::make_shared<BenchArguments>();
    CLI::App* command = app.add_subcommand(
        "bench",
        "Benchmark blob groups: primary, shadow and bounce rays traced directly and as their tessellation, per thread "
        "count");
    command->add_option("scenes", args->scenes, "Scene files with blob groups")->capture_default_str();
    command->add_option("--threads", args->threads, "Thread counts to measure")
        ->capture_default_str()
        ->check(CLI::Range(1, 4096));
    command->add_option("--repeats", args->repeats, "Runs per measurement (the median is reported)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    command->add_option("--resolution", args->resolution, "WIDTHxHEIGHT of the ray grid, or \"scene\"")
        ->capture_default_str();
    args->tessellation.add_to(*command);
    command->add_option("--json", args->json, "Also write the results as JSON to this file");
    command->add_flag("-q,--quiet", args->quiet, "No progress lines on stderr");
    return [args] { return run_bench(*args); };
}

}  // namespace isotrace::cli
