// isotrace benchmark: the frozen suite of tools/cli/benchmark_suite.h on one thread and on all threads, validated
// against the suite's reference outputs and scored against the reference machine (docs/benchmarking.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include "renderer/core/did_you_mean.h"
#include "renderer/core/input_error.h"
#include "tools/cli/benchmark_compare.h"
#include "tools/cli/benchmark_html_report.h"
#include "tools/cli/benchmark_result.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/commands.h"
#include "tools/cli/object_field.h"
#include "tools/cli/progress_bar.h"
#include "tools/cli/system_description.h"

namespace isotrace::cli {
namespace {

struct BenchmarkArguments {
    std::vector<std::string> workloads;  // empty: all
    int threads = 0;                     // of the all-threads run; 0: every hardware thread
    bool short_mode = false;
    bool list = false;
    std::string suite;  // folder; empty: the one installed with the program
    std::string json, report;
    bool quiet = false;
    std::vector<std::string> compare;  // A.json B.json of "benchmark compare"
    CLI::App* compare_command = nullptr;
};

// The suite's workloads named in `names` (all for none), in the suite's order.
std::vector<const BenchmarkWorkload*> selected_workloads(const std::vector<std::string>& names) {
    std::vector<std::string> all;
    for (const BenchmarkWorkload& w : benchmark_workloads()) all.push_back(w.name);
    for (const std::string& name : names)
        if (std::find(all.begin(), all.end(), name) == all.end())
            throw InputError({}, "--workloads",
                             "no workload \"" + name + "\"" + did_you_mean(name, all) + "; workloads: " + joined_names(all));
    std::vector<const BenchmarkWorkload*> selected;
    for (const BenchmarkWorkload& w : benchmark_workloads())
        if (names.empty() || std::find(names.begin(), names.end(), w.name) != names.end()) selected.push_back(&w);
    return selected;
}

std::filesystem::path suite_folder(const std::string& option) {
    if (!option.empty()) {
        std::error_code ignored;
        if (!std::filesystem::is_directory(option, ignored))
            throw InputError({}, "--suite", "\"" + option + "\" is not a folder");
        return option;
    }
    const std::filesystem::path installed = installed_benchmark_folder();
    if (installed.empty())
        throw InputError({}, "--suite",
                         "the benchmark suite is not installed beside this program (share/isotrace/benchmark): "
                         "name its folder");
    return installed;
}

// Progress over the whole run, each unit weighted by its expected time on the reference machine.
class BenchmarkProgress {
public:
    BenchmarkProgress(bool enabled, double planned_seconds) : bar_(enabled), planned_(planned_seconds) {}
    void unit_done(double expected_seconds, const std::string& what) {
        done_ += expected_seconds;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const double fraction = planned_ > 0 ? done_ / planned_ : 0;
        const double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : -1;
        bar_.draw(format_progress(fraction, {format_duration(elapsed) + " elapsed  ETA " + format_duration(eta), what},
                                  terminal_columns()));
    }
    void finish() { bar_.finish(); }

private:
    ProgressBar bar_;
    double planned_, done_ = 0;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The expected seconds of one unit on `threads` threads on the reference machine (1 when unknown).
double expected_unit_seconds(const BenchmarkReference& reference, int threads) {
    const double rate = threads == 1 ? reference.single_thread_rate : reference.all_threads_rate;
    return rate > 0 ? 1 / rate : 1;
}

int run_benchmark(const BenchmarkArguments& args) {
    if (args.compare_command->parsed()) {
        const nlohmann::json a = read_benchmark_result(args.compare[0]);
        const nlohmann::json b = read_benchmark_result(args.compare[1]);
        std::fputs(benchmark_comparison(a, b).c_str(), stdout);
        return kExitOk;
    }
    if (args.list) {
        for (const BenchmarkWorkload& w : benchmark_workloads())
            std::printf("%-20s %s\n", w.name.c_str(), w.measures.c_str());
        return kExitOk;
    }
    const std::vector<const BenchmarkWorkload*> workloads = selected_workloads(args.workloads);
    const std::filesystem::path folder = suite_folder(args.suite);
    const BenchmarkReferences references = read_benchmark_references(folder);
    std::vector<NamedPath> outputs;
    if (!args.json.empty()) outputs.push_back({args.json, "--json", true});
    if (!args.report.empty()) outputs.push_back({args.report, "--report", true});
    std::vector<NamedPath> inputs = {{(folder / "references.json").string(), "the suite's references"}};
    for (const BenchmarkWorkload* w : workloads) inputs.push_back({(folder / w->scene).string(), "a suite scene"});
    check_output_paths(outputs, inputs);

    const int all_threads = args.threads > 0 ? args.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    const std::vector<int> thread_counts = all_threads == 1 ? std::vector<int>{1} : std::vector<int>{1, all_threads};
    const int warm_up = args.short_mode ? 0 : 1;
    const auto units_of = [&](const BenchmarkWorkload& w) { return args.short_mode ? 1 : w.units; };
    double planned = 0;
    for (const BenchmarkWorkload* w : workloads)
        for (int threads : thread_counts)
            planned += (warm_up + units_of(*w)) * expected_unit_seconds(references.workloads.at(w->name), threads);
    BenchmarkProgress progress(!args.quiet && stderr_is_terminal(), planned);

    std::vector<BenchmarkWorkloadResult> results;
    for (const BenchmarkWorkload* w : workloads) {
        const BenchmarkWorkloadRunner runner(*w, folder);
        BenchmarkWorkloadResult result{w, {}};
        for (int threads : thread_counts) {
            const double expected = expected_unit_seconds(references.workloads.at(w->name), threads);
            const std::string what = w->name + " on " + threads_name(threads);
            result.runs.push_back(
                runner.run(threads, warm_up, units_of(*w), [&] { progress.unit_done(expected, what); }));
        }
        results.push_back(std::move(result));
    }
    progress.finish();

    const nlohmann::json result = benchmark_result_json(results, references, args.short_mode, system_description());
    const std::string summary = benchmark_summary(result);
    std::fputs(summary.c_str(), args.json == "-" || args.report == "-" ? stderr : stdout);
    if (!args.json.empty()) write_text_output(args.json, result.dump(2) + "\n");
    if (!args.report.empty()) write_text_output(args.report, benchmark_html_report(result));
    return result["valid"].get<bool>() ? kExitOk : kExitNotMet;
}

}  // namespace

CommandRunner add_benchmark_options(CLI::App* command) {
    auto args = std::make_shared<BenchmarkArguments>();
    command->footer(
        std::string("The frozen suite \"") + kBenchmarkSuite +
        "\": each workload repeats a fixed unit of work (a render, a polygonisation) after a warm-up unit, on one "
        "thread and on all threads, checks every unit's output against the reference output and scores units per "
        "second against the reference machine (1000 there; the overall score is the geometric mean). A full run takes "
        "a few minutes. Exit status: 0 valid, 3 when an output differs from the reference (the score is void; the "
        "outputs are still written), 2 for bad options or a missing or damaged suite.");
    command->add_option("--workloads", args->workloads, "Run only these workloads (no overall score), e.g. blobs_1k,csg_cup")
        ->delimiter(',');
    command->add_option("--threads", args->threads, "Threads of the all-threads run (default: every hardware thread)")
        ->check(CLI::Range(1, 4096));
    command->add_flag("--short", args->short_mode,
                      "One unit per workload and thread count, no warm-up: checks the outputs in about a minute; its "
                      "figures are not scores");
    command->add_flag("--list", args->list, "List the workloads and what each measures, and exit");
    command->add_option("--suite", args->suite,
                        "The suite folder (default: share/isotrace/benchmark/isotrace-bench-1 beside the program)")
        ->type_name("FOLDER");
    command->add_option("--json", args->json, "Also write the result as JSON to this file (\"-\": standard output)")
        ->type_name("PATH");
    command->add_option("--report", args->report, "Also write an HTML page with the result as plots to this file")
        ->type_name("PATH");
    command->add_flag("-q,--quiet", args->quiet, "No progress bar on stderr");
    args->compare_command = command->add_subcommand(
        "compare", "Compare two results (--json files of this suite): B's speed over A's per workload, with 95 % "
                   "confidence intervals");
    args->compare_command->add_option("results", args->compare, "A.json B.json")->required()->expected(2)->check(
        CLI::ExistingFile);
    return [args] { return run_benchmark(*args); };
}

}  // namespace isotrace::cli
