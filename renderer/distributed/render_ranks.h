#pragma once
// This process's place in a distributed render: one of the ranks of an MPI job started by mpirun or srun
// (rank 0 coordinates and writes every output; all ranks render), or the only process. The render command uses
// it the same way in both cases (docs/distributed.md).
#include <memory>
#include <string>
#include <vector>

#include "renderer/core/render_counters.h"
#include "renderer/distributed/distributed_render.h"
#include "renderer/distributed/work_plan.h"
#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace {

// Ranks the launcher started, read from its environment (Open MPI, MPICH/PMI, Slurm's srun); 1 without one.
int launcher_rank_count();

class RenderRanks {
public:
    // Joins the MPI job when the launcher started several ranks, and checks that every rank runs the same
    // `command` ("render", "bench"): ranks running different ones would wait for each other forever. Throws
    // InputError on rank 0 when they do not (the other ranks then leave_quietly()), or when the launcher started
    // several ranks but this build has no MPI (every rank would render the whole image and write the same files).
    explicit RenderRanks(const std::string& command);
    ~RenderRanks();
    RenderRanks(const RenderRanks&) = delete;
    RenderRanks& operator=(const RenderRanks&) = delete;

    int rank() const;
    int count() const;
    bool distributed() const { return count() > 1; }
    bool coordinator() const { return rank() == 0; }
    // This rank found that the job cannot run and leaves with exit code 0: rank 0 reports why and exits with 2,
    // the job's status (a worker exiting with an error first makes the launcher end rank 0 before it has said why).
    bool leave_quietly() const;

    // Every rank loads the scene; rank 0 then checks that all did, with the same isotrace build and the same
    // scene and options (rank_agreement.h), and throws InputError naming the first rank that did not. The other
    // ranks then return null (rank 0 reports the error); rank 0 rethrows its own load error.
    std::unique_ptr<LoadedScene> load_scene(const std::string& path, const SceneOverrides& overrides);

    // Rank 0 (or the only process): renders with every rank and returns the merged result
    // (distributed_render.h says when it throws instead).
    RenderResult render(const LoadedScene& scene, const RenderOptions& options, std::unique_ptr<Film> film,
                        WorkSplit split);
    // The other ranks: render what rank 0 hands out until it has no more.
    void serve(const LoadedScene& scene, int tile_size);

    // Every rank's bytes (index = rank) on rank 0, an empty list on the others: isotrace bench's results.
    std::vector<std::string> gather(const std::string& bytes);

    // After render(): every rank's counters added up, and each rank's share (empty for a single process).
    CounterTotals counter_totals() const;
    const std::vector<RankStatistics>& rank_statistics() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace isotrace
