#include "tools/cli/bench_suite_report.h"

#include <cstdio>

#include "tools/cli/bench_statistics.h"

namespace isotrace::cli {
namespace {

template <class... Args>
std::string format(const char* pattern, Args... args) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, pattern, args...);
    return buffer;
}

}  // namespace

nlohmann::json workload_json(const WorkloadResult& result) {
    nlohmann::json runs = nlohmann::json::array();
    double base_throughput = 0;
    int base_threads = 0;
    for (const RayCastTiming& timing : result.timings) {
        const Spread throughput = spread_of(result.throughputs(timing));
        if (runs.empty()) {
            base_throughput = throughput.median;
            base_threads = timing.threads;
        }
        const double gain = speedup(throughput.median, base_throughput);
        runs.push_back({{"threads", timing.threads},
                        {"seconds", timing.seconds},
                        {"passes", timing.passes},
                        {"median_seconds", timing.median_seconds()},
                        {"throughput",
                         {{"median", throughput.median},
                          {"min", throughput.min},
                          {"q1", throughput.q1},
                          {"q3", throughput.q3},
                          {"max", throughput.max}}},
                        {"speedup", gain},
                        {"efficiency", parallel_efficiency(gain, timing.threads, base_threads)}});
    }
    return {{"name", result.workload.name},
            {"scene", result.workload.scene},
            {"kind", kind_name(result.workload.kind)},
            {"unit", result.unit},
            {"work_per_run", result.work_per_run},
            {"build_seconds", result.build_seconds},
            {"scene_bytes", result.scene_bytes},
            {"peak_memory_bytes", result.peak_memory_bytes},
            {"runs", runs}};
}

nlohmann::json scaling_json(const std::vector<ScalingPoint>& points) {
    nlohmann::json list = nlohmann::json::array();
    for (const ScalingPoint& p : points)
        list.push_back({{"elements", p.elements},
                        {"rays", p.rays},
                        {"build_seconds", p.build_seconds},
                        {"bytes_per_element", p.bytes_per_element},
                        {"ns_per_ray", p.nanoseconds_per_ray},
                        {"cost_growth", p.cost_growth}});
    return list;
}

std::string suite_table(const nlohmann::json& report) {
    const auto& machine = report["machine"];
    const auto& settings = report["settings"];
    std::string out =
        format("isotrace bench: %s, %u cores, Embree ISA %s, blob march %s; warm-up + %d run(s) per thread count\n",
               machine["cpu"].get<std::string>().c_str(), machine["cores"].get<unsigned>(),
               machine["embree_isa"].get<std::string>().c_str(),
               machine.value("blob_march_isa", std::string("unknown")).c_str(), settings["repeats"].get<int>());
    const auto& workloads = report["workloads"];
    if (!workloads.empty()) {
        out += format("\n%-30s %-13s %7s %10s %10s %10s %9s %9s %10s\n", "workload", "unit", "threads", "median",
                      "min", "max", "build ms", "peak MiB", "work/run");
        for (const auto& w : workloads)
            for (const auto& run : w["runs"]) {
                const bool first = &run == &w["runs"].front();
                out += format("%-30s %-13s %7d %10.4g %10.4g %10.4g", first ? w["name"].get<std::string>().c_str() : "",
                              first ? w["unit"].get<std::string>().c_str() : "", run["threads"].get<int>(),
                              run["throughput"]["median"].get<double>(), run["throughput"]["min"].get<double>(),
                              run["throughput"]["max"].get<double>());
                out += first ? format(" %9.1f %9.1f %10.0f\n", w["build_seconds"].get<double>() * 1e3,
                                      double(w["peak_memory_bytes"].get<std::uint64_t>()) / (1 << 20),
                                      w["work_per_run"].get<double>())
                             : std::string("\n");
            }
    }
    if (settings["threads"].size() > 1 && !workloads.empty()) {
        out += format("\nThread scaling (relative to %d thread(s))\n%-30s %7s %10s %10s\n",
                      settings["threads"][0].get<int>(), "workload", "threads", "speed-up", "efficiency");
        for (const auto& w : workloads)
            for (const auto& run : w["runs"])
                out += format("%-30s %7d %9.2fx %9.0f%%\n",
                              &run == &w["runs"].front() ? w["name"].get<std::string>().c_str() : "",
                              run["threads"].get<int>(), run["speedup"].get<double>(),
                              100 * run["efficiency"].get<double>());
    }
    const auto& scaling = report["scaling"];
    if (scaling.is_object()) {
        out += format("\nElement-count scaling: blobs at a fixed density, primary rays on %d thread(s)\n",
                      scaling["threads"].get<int>());
        out += format("%10s %9s %10s %12s %9s %10s\n", "elements", "rays", "ns/ray", "cost growth", "build ms",
                      "bytes/elem");
        for (const auto& p : scaling["points"])
            out += format("%10zu %9zu %10.1f %11.2fx %9.1f %10.0f\n", p["elements"].get<std::size_t>(),
                          p["rays"].get<std::size_t>(), p["ns_per_ray"].get<double>(), p["cost_growth"].get<double>(),
                          p["build_seconds"].get<double>() * 1e3, p["bytes_per_element"].get<double>());
    }
    return out;
}

}  // namespace isotrace::cli
