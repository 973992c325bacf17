#pragma once
// Runs one workload of isotrace benchmark (tools/cli/benchmark_suite.h): loads its scene once, then times units
// of work on a given number of threads and hashes each unit's output (the film's accumulators, or the mesh), so
// that the result can be checked against the suite's reference.
#include <filesystem>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "renderer/scene/loaded_scene.h"
#include "tools/cli/benchmark_suite.h"

namespace isotrace::cli {

struct BenchmarkRun {
    int threads = 1;
    std::vector<double> seconds;   // per timed unit (the warm-up left out)
    std::set<std::string> hashes;  // of every unit's output, the warm-up's included: one when deterministic
};

class BenchmarkWorkloadRunner {
public:
    // Throws InputError when the scene is missing or invalid.
    BenchmarkWorkloadRunner(const BenchmarkWorkload& workload, const std::filesystem::path& folder);
    ~BenchmarkWorkloadRunner();

    // `warm_up` untimed units (0 or 1), then `units` timed ones on `threads` threads; `on_unit` after each.
    BenchmarkRun run(int threads, int warm_up, int units, const std::function<void()>& on_unit) const;

private:
    std::string unit() const;  // does one unit, returns its output's hash

    const BenchmarkWorkload& workload_;
    std::unique_ptr<LoadedScene> scene_;
};

}  // namespace isotrace::cli
