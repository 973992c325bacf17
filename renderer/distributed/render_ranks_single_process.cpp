// RenderRanks without MPI (ISOTRACE_MPI=OFF): always the only process.
#include <stdexcept>

#include "renderer/core/input_error.h"
#include "renderer/distributed/render_ranks.h"

namespace isotrace {

struct RenderRanks::State {
    std::vector<RankStatistics> no_ranks;
};

RenderRanks::RenderRanks(const std::string&) : state_(std::make_unique<State>()) {
    if (const int launched = launcher_rank_count(); launched > 1)
        throw InputError({}, "",
                         "started as one of " + std::to_string(launched) +
                             " MPI ranks, but this isotrace was built without MPI (ISOTRACE_MPI=OFF): each rank "
                             "would render the whole image; rebuild with Open MPI installed or run one process");
}

RenderRanks::~RenderRanks() = default;

int RenderRanks::rank() const { return 0; }
int RenderRanks::count() const { return 1; }
bool RenderRanks::leave_quietly() const { return false; }

std::unique_ptr<LoadedScene> RenderRanks::load_scene(const std::string& path, const SceneOverrides& overrides) {
    return isotrace::load_scene(path, overrides);
}

RenderResult RenderRanks::render(const LoadedScene& scene, const RenderOptions& options, std::unique_ptr<Film> film,
                                 WorkSplit) {
    return render_scene(scene, options, std::move(film));
}

void RenderRanks::serve(const LoadedScene&, int) {
    throw std::logic_error("RenderRanks::serve: a single process has no coordinator to serve");
}

std::vector<std::string> RenderRanks::gather(const std::string& bytes) { return {bytes}; }

CounterTotals RenderRanks::counter_totals() const { return counters::totals(); }

const std::vector<RankStatistics>& RenderRanks::rank_statistics() const { return state_->no_ranks; }

}  // namespace isotrace
