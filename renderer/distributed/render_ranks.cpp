// RenderRanks with MPI (ISOTRACE_MPI=ON).
#include "renderer/distributed/render_ranks.h"

#include <mpi.h>

#include <exception>
#include <stdexcept>

#include "renderer/core/input_error.h"
#include "renderer/distributed/mpi_channel.h"
#include "renderer/distributed/rank_agreement.h"

namespace isotrace {

struct RenderRanks::State {
    int rank = 0, count = 1;
    bool joined = false;  // MPI_Init was called
    // Every rank is at a point where MPI_Finalize can complete: nobody waits for a message that will not come.
    // False while an interrupted render or its service is unwinding: the process then leaves without finalising
    // and the launcher ends the other ranks.
    bool in_step = true;
    bool other_commands = false;  // a worker saw ranks running different commands
    bool workers_waiting = false;  // rank 0: the workers wait for work in serve(); released with Done
    std::vector<std::string> hosts;
    CounterTotals counters;
    std::vector<RankStatistics> ranks;
};

namespace {

// The first rank whose command differs from this one's, as "rank N runs \"isotrace X\"", or "" when all agree.
// Names travel in fixed slots, the only message every rank can take part in whatever it runs.
std::string other_command(const std::string& command, int count) {
    constexpr int kSlot = 32;
    char own[kSlot] = {};
    command.copy(own, kSlot - 1);
    std::vector<char> all(std::size_t(count) * kSlot);
    MPI_Allgather(own, kSlot, MPI_CHAR, all.data(), kSlot, MPI_CHAR, MPI_COMM_WORLD);
    for (int rank = 0; rank < count; ++rank) {
        const std::string name(all.data() + std::size_t(rank) * kSlot);
        if (name != own) return "rank " + std::to_string(rank) + " runs \"isotrace " + name + "\"";
    }
    return "";
}

}  // namespace

RenderRanks::RenderRanks(const std::string& command) : state_(std::make_unique<State>()) {
    const int launched = launcher_rank_count();
    if (launched <= 1) return;
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    state_->joined = true;
    state_->rank = mpi::world_rank();
    state_->count = mpi::world_size();
    if (state_->count == 1)  // e.g. srun without an MPI plugin: each task would render and write the whole image
        throw InputError({}, "",
                         "the launcher started " + std::to_string(launched) +
                             " tasks but MPI sees this one alone: start the ranks with mpirun, or srun with the "
                             "MPI plugin your Open MPI uses (srun --mpi=pmix)");
    if (provided < MPI_THREAD_FUNNELED)
        throw std::runtime_error("the MPI library does not allow threads (MPI_THREAD_FUNNELED)");
    const std::string other = other_command(command, state_->count);
    if (other.empty()) return;
    if (!coordinator()) {
        state_->other_commands = true;
        return;
    }
    MPI_Finalize();  // the destructor of a half-made object does not run; the workers finalise in theirs
    throw InputError({}, "",
                     "every rank of a job must run the same command, but rank 0 runs \"isotrace " + command +
                         "\" and " + other);
}

bool RenderRanks::leave_quietly() const { return state_->other_commands; }

RenderRanks::~RenderRanks() {
    if (!state_->joined) return;
    if (state_->workers_waiting)
        for (int worker = 1; worker < state_->count; ++worker) mpi::send(worker, mpi::Tag::Done, {});
    if (state_->in_step) MPI_Finalize();
}

int RenderRanks::rank() const { return state_->rank; }
int RenderRanks::count() const { return state_->count; }

std::unique_ptr<LoadedScene> RenderRanks::load_scene(const std::string& path, const SceneOverrides& overrides) {
    if (!distributed()) return isotrace::load_scene(path, overrides);
    std::unique_ptr<LoadedScene> scene;
    std::exception_ptr failure;
    std::string error;
    try {
        scene = isotrace::load_scene(path, overrides);
    } catch (const std::exception& e) {
        failure = std::current_exception();
        error = e.what();
    }
    const RankIdentity own = identify_this_rank(scene.get(), error);
    const std::string kGo = "go";
    if (!coordinator()) {
        mpi::send(0, mpi::Tag::Identity, encode_identity(own));
        const mpi::Message verdict = mpi::receive(0);
        if (verdict.tag != mpi::Tag::Verdict) throw std::runtime_error("distributed render: unexpected message from rank 0");
        return verdict.bytes == kGo ? std::move(scene) : nullptr;
    }
    std::vector<RankIdentity> identities{own};
    for (int worker = 1; worker < count(); ++worker)
        identities.push_back(decode_identity(mpi::receive(worker).bytes));
    for (const RankIdentity& identity : identities) state_->hosts.push_back(identity.host);
    const std::string problem = failure ? std::string() : disagreement(identities);
    const bool go = !failure && problem.empty();
    for (int worker = 1; worker < count(); ++worker) mpi::send(worker, mpi::Tag::Verdict, go ? kGo : "stop");
    if (failure) std::rethrow_exception(failure);
    if (!go) throw InputError({}, "", problem);
    state_->workers_waiting = true;
    return scene;
}

RenderResult RenderRanks::render(const LoadedScene& scene, const RenderOptions& options, std::unique_ptr<Film> film,
                                 WorkSplit split) {
    if (!distributed()) return render_scene(scene, options, std::move(film));
    DistributedRenderResult result;
    try {
        result = coordinate_render(scene, options, std::move(film), split, state_->hosts);
    } catch (const InputError&) {
        throw;  // raised before any work was handed out: the workers still wait and are released with Done
    } catch (...) {
        state_->workers_waiting = false;
        state_->in_step = false;
        throw;
    }
    state_->workers_waiting = false;  // each was told Done when the work ran out
    state_->counters = std::move(result.counters);
    state_->ranks = std::move(result.ranks);
    return std::move(result.render);
}

void RenderRanks::serve(const LoadedScene& scene, int tile_size) {
    state_->in_step = false;
    serve_render_work(scene, tile_size);
    state_->in_step = true;
}

std::vector<std::string> RenderRanks::gather(const std::string& bytes) {
    if (!distributed()) return {bytes};
    if (!coordinator()) {
        mpi::send(0, mpi::Tag::Bench, bytes);
        return {};
    }
    std::vector<std::string> all{bytes};
    for (int worker = 1; worker < count(); ++worker) all.push_back(mpi::receive(worker).bytes);
    return all;
}

CounterTotals RenderRanks::counter_totals() const { return distributed() ? state_->counters : counters::totals(); }

const std::vector<RankStatistics>& RenderRanks::rank_statistics() const { return state_->ranks; }

}  // namespace isotrace
