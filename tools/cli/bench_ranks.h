#pragma once
// isotrace bench under mpirun or srun: every rank runs the same workloads from its start, concurrently with the
// others (no barrier: a rank that fails must not leave the others waiting), and rank 0 reports each rank's median
// throughput and their sum, the aggregate throughput of the job (docs/distributed.md).
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace isotrace::cli {

// From each rank's report["workloads"] (index = rank): {"ranks": N, "workloads": [{name, unit, runs: [{threads,
// per_rank: [median throughput of each rank], total}]}]}. Workloads are matched by name and thread count.
nlohmann::json rank_aggregate(const std::vector<nlohmann::json>& rank_workloads);

std::string rank_aggregate_table(const nlohmann::json& aggregate);

}  // namespace isotrace::cli
