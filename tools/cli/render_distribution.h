#pragma once
// isotrace render under mpirun or srun (docs/distributed.md): the --distribute option and each rank's share in
// the statistics.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <string>

#include "renderer/distributed/render_ranks.h"

namespace isotrace::cli {

struct DistributionArguments {
    std::string split = "tiles";
};

void add_distribution_options(CLI::App& command, DistributionArguments& args);
WorkSplit work_split(const DistributionArguments& args);

// Under mpirun or srun stderr is a pipe, not a terminal: rank 0 reports the merged progress as a line every
// `every_seconds` and at the end, instead of a progress bar.
std::function<void(const RenderProgress&)> progress_lines(double every_seconds);

// Adds "ranks": items, samples, rays, busy time and Mrays/s of each rank (nothing for a single process).
void add_rank_statistics(nlohmann::json& stats, const RenderRanks& ranks);

}  // namespace isotrace::cli
