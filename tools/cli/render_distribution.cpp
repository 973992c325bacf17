#include "tools/cli/render_distribution.h"

#include <cstdio>
#include <memory>

namespace isotrace::cli {

void add_distribution_options(CLI::App& command, DistributionArguments& args) {
    command
        .add_option("--distribute", args.split,
                    "Under mpirun or srun, how the ranks share the work: tiles (regions of the image, default) or "
                    "samples (blocks of 32 sample indices of every pixel); the image is bit-identical either way")
        ->check(CLI::IsMember({"tiles", "samples"}))
        ->capture_default_str();
}

WorkSplit work_split(const DistributionArguments& args) {
    return args.split == "samples" ? WorkSplit::Samples : WorkSplit::Tiles;
}

std::function<void(const RenderProgress&)> progress_lines(double every_seconds) {
    auto next = std::make_shared<double>(every_seconds);
    return [next, every_seconds](const RenderProgress& p) {
        if (p.elapsed_seconds < *next && p.fraction < 1) return;
        *next = p.elapsed_seconds + every_seconds;
        std::fprintf(stderr, "isotrace: %5.1f %% after %.0f s, %d spp in every pixel, %.3g rays on all ranks%s\n",
                     100 * p.fraction, p.elapsed_seconds, p.completed_spp, double(p.rays),
                     p.eta_seconds >= 0 && p.fraction < 1
                         ? (", about " + std::to_string(int(p.eta_seconds + 0.5)) + " s to go").c_str()
                         : "");
    };
}

void add_rank_statistics(nlohmann::json& stats, const RenderRanks& ranks) {
    if (ranks.rank_statistics().empty()) return;
    nlohmann::json rows = nlohmann::json::array();
    for (const RankStatistics& rank : ranks.rank_statistics())
        rows.push_back({{"rank", rank.rank},
                        {"host", rank.host},
                        {"items", rank.items},
                        {"samples", rank.samples},
                        {"rays", rank.rays},
                        {"busy_seconds", rank.busy_seconds},
                        {"mrays_per_second", rank.busy_seconds > 0 ? double(rank.rays) / rank.busy_seconds * 1e-6 : 0.0}});
    stats["ranks"] = rows;
}

}  // namespace isotrace::cli
