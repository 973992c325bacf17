#pragma once
// The result of isotrace benchmark as JSON (docs/benchmarking.md describes the schema), its validation against
// the suite's references, its scores, and the human summary printed from it.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "tools/cli/benchmark_run.h"
#include "tools/cli/benchmark_suite.h"

namespace isotrace::cli {

// Version of the result's layout (not of the suite, which "benchmark" names).
inline constexpr int kBenchmarkResultFormat = 1;

// One workload's runs: one per thread count, in increasing thread order.
struct BenchmarkWorkloadResult {
    const BenchmarkWorkload* workload = nullptr;
    std::vector<BenchmarkRun> runs;
};

// {"benchmark", "result_format", "mode", "valid", "problems", "system", "reference_machine", "threads",
//  "workloads": [{"name", "measures", "units_per_run", "hash", "reference_hash", "valid",
//                 "runs": [{"threads", "units", "seconds", "unit_seconds", "units_per_second", "units_per_second_min",
//                           "units_per_second_max", "score", "score_min", "score_max"}]}],
//  "scores": [{"threads", "score", "score_min", "score_max"}]}.
// A workload is valid when all its units gave one hash, the reference's; the result is valid when every workload
// is. Scores are units per second over the reference machine's, times 1000 (its geometric mean over the workloads
// for "scores"), null when the result is invalid or short, a reference rate is missing or (overall) not every
// workload ran.
nlohmann::json benchmark_result_json(const std::vector<BenchmarkWorkloadResult>& results,
                                     const BenchmarkReferences& references, bool short_mode,
                                     const nlohmann::json& system);

// The geometric mean of positive values; 0 for none.
double geometric_mean(const std::vector<double>& values);

// The system facts as people read them: caches as "L1 data 32 KiB x2, ...", clocks as "current 2445 MHz", memory
// in GiB, true and false as "yes" and "no", null as "unknown"; other values as they are (strings) or as JSON.
std::string readable_system_fact(const std::string& key, const nlohmann::json& value);

// "1 thread", "2 threads".
std::string threads_name(int threads);

// The table and the score lines, from a result.
std::string benchmark_summary(const nlohmann::json& result);

}  // namespace isotrace::cli
