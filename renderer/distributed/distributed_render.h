#pragma once
// The work queue of a distributed render over MPI (docs/distributed.md). Rank 0 hands out work items
// (work_plan.h) one at a time to whichever rank asks next — its own rendering thread included — so faster ranks
// take more; it merges the returned films in an order that keeps every pixel's sums bit-identical to a single
// process (Film::append_block, Film::replace_region), writes the checkpoints and reports the progress. The other
// ranks render the items they are given.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "renderer/core/render_counters.h"
#include "renderer/distributed/work_plan.h"
#include "renderer/render/tile_renderer.h"

namespace isotrace {

struct RankStatistics {
    int rank = 0;
    std::string host;
    std::size_t items = 0;
    std::uint64_t samples = 0;  // camera samples it took
    std::uint64_t rays = 0;
    double busy_seconds = 0;    // rendering items
};

struct DistributedRenderResult {
    RenderResult render;
    std::vector<RankStatistics> ranks;  // index = rank
    CounterTotals counters;             // of every rank
};

// Rank 0. `film` is a resumed film or null; `hosts` names each rank's machine. Throws InputError when the work
// cannot be divided among the ranks and std::runtime_error when options.cancel stops the render (a signal: the
// job is being ended), after writing a checkpoint when options.on_checkpoint is set; no image is then written.
DistributedRenderResult coordinate_render(const LoadedScene& scene, const RenderOptions& options,
                                          std::unique_ptr<Film> film, WorkSplit split,
                                          const std::vector<std::string>& hosts);

// The other ranks: render items until rank 0 says there are no more, then send this rank's counters.
void serve_render_work(const LoadedScene& scene, int tile_size);

}  // namespace isotrace
