#include "tools/cli/bench_ranks.h"

#include <cstdio>
#include <stdexcept>

namespace isotrace::cli {
namespace {

const nlohmann::json& run_of(const nlohmann::json& workloads, const std::string& name, int threads, std::size_t rank) {
    for (const auto& w : workloads)
        if (w["name"] == name)
            for (const auto& run : w["runs"])
                if (run["threads"] == threads) return run;
    throw std::runtime_error("isotrace bench: rank " + std::to_string(rank) + " has no result for " + name + " on " +
                             std::to_string(threads) + " thread(s)");
}

}  // namespace

nlohmann::json rank_aggregate(const std::vector<nlohmann::json>& rank_workloads) {
    nlohmann::json workloads = nlohmann::json::array();
    for (const auto& w : rank_workloads.front()) {
        nlohmann::json runs = nlohmann::json::array();
        for (const auto& run : w["runs"]) {
            const int threads = run["threads"].get<int>();
            nlohmann::json per_rank = nlohmann::json::array();
            double total = 0;
            for (std::size_t rank = 0; rank < rank_workloads.size(); ++rank) {
                const double median =
                    run_of(rank_workloads[rank], w["name"], threads, rank)["throughput"]["median"].get<double>();
                per_rank.push_back(median);
                total += median;
            }
            runs.push_back({{"threads", threads}, {"per_rank", per_rank}, {"total", total}});
        }
        workloads.push_back({{"name", w["name"]}, {"unit", w["unit"]}, {"runs", runs}});
    }
    return {{"ranks", rank_workloads.size()}, {"workloads", workloads}};
}

std::string rank_aggregate_table(const nlohmann::json& aggregate) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "\nAggregate of %zu ranks (run concurrently, each from its start; each rank's median throughput, summed)\n"
                  "%-30s %-13s %7s %10s  %s\n",
                  aggregate["ranks"].get<std::size_t>(), "workload", "unit", "threads", "total", "per rank");
    std::string out = line;
    for (const auto& w : aggregate["workloads"])
        for (const auto& run : w["runs"]) {
            const bool first = &run == &w["runs"].front();
            std::string per_rank;
            for (const auto& value : run["per_rank"]) {
                std::snprintf(line, sizeof line, "%s%.4g", per_rank.empty() ? "" : " ", value.get<double>());
                per_rank += line;
            }
            std::snprintf(line, sizeof line, "%-30s %-13s %7d %10.4g  %s\n",
                          first ? w["name"].get<std::string>().c_str() : "",
                          first ? w["unit"].get<std::string>().c_str() : "", run["threads"].get<int>(),
                          run["total"].get<double>(), per_rank.c_str());
            out += line;
        }
    return out;
}

}  // namespace isotrace::cli
