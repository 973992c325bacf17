#include "renderer/distributed/distributed_render.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "renderer/core/input_error.h"
#include "renderer/distributed/counter_messages.h"
#include "renderer/distributed/message_bytes.h"
#include "renderer/distributed/mpi_channel.h"

namespace isotrace {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

FilmSettings region_settings(const LoadedScene& scene, const PixelBounds& region) {
    FilmSettings settings = scene.film;
    settings.crop = region;
    return settings;
}

std::uint64_t samples_in(const Film& film) { return film.sample_count_range().total; }

// An item handed out: its film as rendering starts from it.
struct Assignment {
    std::size_t index = 0;
    std::unique_ptr<Film> start;
};

// A rendered item: its film and what it cost.
struct Finished {
    std::size_t index = 0;
    std::unique_ptr<Film> film;
    std::uint64_t samples = 0;
    double seconds = 0;
};

// Brings the item's film up to its last sample; null when `cancel` stopped it first.
std::optional<Finished> render_item(const LoadedScene& scene, const WorkItem& item, Assignment assignment,
                                    int tile_size, const std::atomic<bool>* cancel) {
    const auto start = Clock::now();
    const std::uint64_t samples_before = samples_in(*assignment.start);
    RenderOptions options;
    options.tile_size = tile_size;
    options.spp = int(item.last_sample);
    options.cancel = cancel;
    RenderResult result = render_scene(scene, options, std::move(assignment.start));
    if (result.cancelled) return std::nullopt;
    const std::uint64_t samples = samples_in(*result.film) - samples_before;
    return Finished{assignment.index, std::move(result.film), samples, seconds_since(start)};
}

std::string encode_work(const WorkItem& item, const Assignment& assignment, bool send_state) {
    MessageWriter out;
    out.put(std::uint64_t(assignment.index)).put(item.region).put(item.first_sample).put(item.last_sample);
    out.put(send_state);
    if (send_state) out.put_string(assignment.start->state());
    return out.take();
}

class Coordinator {
public:
    Coordinator(const LoadedScene& scene, const RenderOptions& options, std::unique_ptr<Film> film, WorkSplit split,
                const std::vector<std::string>& hosts)
        : scene_(scene), options_(options), split_(split), resumed_(film != nullptr) {
        merged_ = film ? std::move(film) : std::make_unique<Film>(scene.film);
        const auto spp = std::uint32_t(options.spp);
        if (split == WorkSplit::Tiles) {
            items_ = plan_tiles(*merged_, options.tile_size, spp, 4 * hosts.size());
        } else {
            const SampleCountRange counts = merged_->sample_count_range();
            if (counts.min != counts.max || (counts.min % Film::kSampleBlock != 0 && counts.min < spp))
                throw InputError({}, "--distribute",
                                 "samples needs a resumed render whose pixels all have the same multiple of " +
                                     std::to_string(Film::kSampleBlock) + " samples; this one has " +
                                     std::to_string(counts.min) + " to " + std::to_string(counts.max) +
                                     ": finish it with --distribute tiles");
            items_ = plan_sample_blocks(merged_->bounds(), counts.min, spp);
        }
        if (!resumed_ && items_.size() < hosts.size())
            throw InputError({}, "", too_many_ranks_message(hosts.size()));
        merged_items_.assign(items_.size(), false);
        ranks_.resize(hosts.size());
        for (std::size_t r = 0; r < hosts.size(); ++r) ranks_[r] = {int(r), hosts[r]};
    }

    DistributedRenderResult run() {
        const auto start = Clock::now();
        std::exception_ptr local_failure;
        std::thread local([&] {
            try {
                render_locally();
            } catch (...) {
                local_failure = std::current_exception();
            }
        });
        std::size_t workers_active = ranks_.size() - 1;
        auto next_checkpoint = start + seconds(options_.checkpoint_interval_seconds.value_or(0));
        auto next_progress = start;
        try {
            while (!stopped() && !(all_merged() && workers_active == 0 && local_done_)) {
                merge_local_results();
                if (std::optional<mpi::Message> message = mpi::try_receive()) {
                    if (message->tag == mpi::Tag::Counters) {
                        add_counters(counters_, decode_counters(message->bytes));
                        --workers_active;
                    } else {
                        if (message->tag == mpi::Tag::Result) merge_result(message->from, message->bytes);
                        else if (message->tag != mpi::Tag::Ready) throw std::runtime_error("distributed render: unexpected message");
                        hand_out(message->from);
                    }
                    continue;
                }
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
                const auto now = Clock::now();
                if (options_.on_checkpoint && options_.checkpoint_interval_seconds && now >= next_checkpoint) {
                    checkpoint();
                    next_checkpoint = Clock::now() + seconds(*options_.checkpoint_interval_seconds);
                }
                if (options_.on_progress && now >= next_progress) {
                    options_.on_progress(progress(seconds_since(start)));
                    next_progress = now + std::chrono::milliseconds(200);
                }
            }
        } catch (...) {
            stop_local_ = true;
            local.join();
            throw;
        }
        local.join();
        if (local_failure) std::rethrow_exception(local_failure);
        merge_local_results();
        if (stopped()) {
            if (options_.on_checkpoint) checkpoint();
            throw std::runtime_error(
                "the distributed render was stopped by a signal before it finished: no image written. When a rank "
                "dies, the MPI launcher stops the others (its message names the rank)" +
                std::string(options_.on_checkpoint ? "; the checkpoint holds the finished work: continue with --resume"
                                                   : ""));
        }
        return finish(seconds_since(start));
    }

private:
    static Clock::duration seconds(double s) {
        return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
    }

    bool stopped() const { return options_.cancel && options_.cancel->load(); }
    bool all_merged() const { return merged_count_ == items_.size(); }

    std::string too_many_ranks_message(std::size_t ranks) const {
        const std::string unit = split_ == WorkSplit::Tiles ? "region" : "block of samples";
        return std::to_string(ranks) + " ranks but the work divides into only " + std::to_string(items_.size()) +
               " " + unit + (items_.size() == 1 ? "" : "s") + " (--distribute " +
               (split_ == WorkSplit::Tiles ? "tiles" : "samples") + "): use at most " + std::to_string(items_.size()) +
               (items_.size() == 1 ? " rank, " : " ranks, ") +
               (split_ == WorkSplit::Tiles ? "a smaller --tile-size or --distribute samples"
                                           : "more samples (blocks of " + std::to_string(Film::kSampleBlock) +
                                                 ") or --distribute tiles");
    }

    // The next item and its starting film, or nothing when all are handed out. Tiles start from the merged film's
    // region (a resumed render's counts); sample blocks from zero at their first sample.
    std::optional<Assignment> take() {
        std::lock_guard lock(mutex_);
        if (next_ == items_.size()) return std::nullopt;
        const WorkItem& item = items_[next_];
        Assignment assignment{next_++, nullptr};
        assignment.start = split_ == WorkSplit::Tiles
                               ? std::make_unique<Film>(merged_->region(item.region))
                               : std::make_unique<Film>(region_settings(scene_, item.region), item.first_sample);
        return assignment;
    }

    void hand_out(int rank) {
        std::optional<Assignment> assignment = take();
        if (!assignment) {
            mpi::send(rank, mpi::Tag::Done, {});
            return;
        }
        const bool send_state = samples_in(*assignment->start) > 0 && split_ == WorkSplit::Tiles;
        mpi::send(rank, mpi::Tag::Work, encode_work(items_[assignment->index], *assignment, send_state));
    }

    void render_locally() {
        while (!stop_local_ && !stopped()) {
            std::optional<Assignment> assignment = take();
            if (!assignment) break;
            const std::size_t index = assignment->index;
            std::optional<Finished> finished =
                render_item(scene_, items_[index], std::move(*assignment), options_.tile_size, options_.cancel);
            if (!finished) break;
            std::lock_guard lock(mutex_);
            local_results_.push_back(std::move(*finished));
        }
        local_done_ = true;
    }

    void merge_local_results() {
        std::vector<Finished> results;
        {
            std::lock_guard lock(mutex_);
            results.swap(local_results_);
        }
        for (Finished& finished : results) {
            account(0, finished, counters::totals().total_rays());
            merge(finished.index, std::move(finished.film));
        }
    }

    void merge_result(int rank, const std::string& bytes) {
        MessageReader in(bytes);
        Finished finished;
        finished.index = std::size_t(in.get<std::uint64_t>());
        finished.samples = in.get<std::uint64_t>();
        finished.seconds = in.get<double>();
        const auto rays = in.get<std::uint64_t>();
        if (finished.index >= items_.size()) throw std::runtime_error("distributed render: result of an unknown item");
        finished.film = std::make_unique<Film>(region_settings(scene_, items_[finished.index].region));
        finished.film->restore_state(in.get_string());
        account(rank, finished, rays);
        merge(finished.index, std::move(finished.film));
    }

    void account(int rank, const Finished& finished, std::uint64_t rays) {
        RankStatistics& stats = ranks_[std::size_t(rank)];
        ++stats.items;
        stats.samples += finished.samples;
        stats.busy_seconds += finished.seconds;
        stats.rays = rays;  // the rank's running total
    }

    // Tiles replace their region. A block of samples is appended once the block before it for the same pixels
    // is in; until then it waits (at most one per item in flight).
    void merge(std::size_t index, std::unique_ptr<Film> film) {
        std::lock_guard lock(mutex_);
        const WorkItem& item = items_[index];
        if (split_ == WorkSplit::Tiles) {
            merged_->replace_region(*film);
            mark_merged(index);
            return;
        }
        if (item.previous && !merged_items_[*item.previous]) {
            waiting_.emplace(*item.previous, std::make_pair(index, std::move(film)));
            return;
        }
        for (;;) {
            merged_->append_block(*film);
            mark_merged(index);
            const auto next = waiting_.find(index);
            if (next == waiting_.end()) return;
            index = next->second.first;
            film = std::move(next->second.second);
            waiting_.erase(next);
        }
    }

    void mark_merged(std::size_t index) {
        merged_items_[index] = true;
        ++merged_count_;
    }

    void checkpoint() {
        std::lock_guard lock(mutex_);
        options_.on_checkpoint(*merged_);
        ++checkpoints_;
    }

    RenderProgress progress(double elapsed) {
        RenderProgress p;
        p.elapsed_seconds = elapsed;
        std::lock_guard lock(mutex_);
        const SampleCountRange counts = merged_->sample_count_range();
        p.fraction = double(counts.total) / std::max(1.0, double(merged_->bounds().area()) * options_.spp);
        if (p.fraction > 0) p.eta_seconds = elapsed * (1 - p.fraction) / p.fraction;
        p.completed_spp = int(counts.min);
        p.rays = counters::totals().total_rays();
        for (std::size_t r = 1; r < ranks_.size(); ++r) p.rays += ranks_[r].rays;
        return p;
    }

    DistributedRenderResult finish(double seconds) {
        DistributedRenderResult out;
        const SampleCountRange counts = merged_->sample_count_range();
        out.render.completed_spp = int(counts.min);
        out.render.max_spp = int(counts.max);
        out.render.partial = counts.min != counts.max;
        out.render.checkpoints = checkpoints_;
        out.render.seconds = seconds;
        out.render.film = std::move(merged_);
        const CounterTotals own = counters::totals();
        ranks_[0].rays = own.total_rays();
        add_counters(counters_, own);
        out.counters = std::move(counters_);
        out.ranks = std::move(ranks_);
        if (options_.on_progress) {
            RenderProgress last;
            last.fraction = 1;
            last.eta_seconds = 0;
            last.elapsed_seconds = seconds;
            last.completed_spp = out.render.completed_spp;
            last.rays = out.counters.total_rays();
            options_.on_progress(last);
        }
        return out;
    }

    const LoadedScene& scene_;
    const RenderOptions& options_;
    const WorkSplit split_;
    const bool resumed_;
    std::vector<WorkItem> items_;
    std::mutex mutex_;  // guards what the local rendering thread shares: next_, merged_, local_results_
    std::unique_ptr<Film> merged_;
    std::size_t next_ = 0;
    std::vector<bool> merged_items_;
    std::size_t merged_count_ = 0;
    std::map<std::size_t, std::pair<std::size_t, std::unique_ptr<Film>>> waiting_;  // by the item they follow
    std::vector<Finished> local_results_;
    std::atomic<bool> local_done_{false}, stop_local_{false};
    std::vector<RankStatistics> ranks_;
    CounterTotals counters_;
    int checkpoints_ = 0;
};

}  // namespace

DistributedRenderResult coordinate_render(const LoadedScene& scene, const RenderOptions& options,
                                          std::unique_ptr<Film> film, WorkSplit split,
                                          const std::vector<std::string>& hosts) {
    if (options.time_budget_seconds)
        throw InputError({}, "--time",
                         "is not available in a distributed render (its ranks could not stop on the same sample); "
                         "use --checkpoint and end the job instead");
    if (options.stop_at_pass_end)
        throw InputError({}, "--reference",
                         "is not available in a distributed render (the error estimate is decided from the whole "
                         "film at pass boundaries); render the reference in one process");
    return Coordinator(scene, options, std::move(film), split, hosts).run();
}

void serve_render_work(const LoadedScene& scene, int tile_size) {
    mpi::send(0, mpi::Tag::Ready, {});
    for (;;) {
        const mpi::Message message = mpi::receive(0);
        if (message.tag == mpi::Tag::Done) break;
        if (message.tag != mpi::Tag::Work) throw std::runtime_error("distributed render: unexpected message from rank 0");
        MessageReader in(message.bytes);
        Assignment assignment;
        assignment.index = std::size_t(in.get<std::uint64_t>());
        WorkItem item;
        item.region = in.get<PixelBounds>();
        item.first_sample = in.get<std::uint32_t>();
        item.last_sample = in.get<std::uint32_t>();
        const FilmSettings settings = region_settings(scene, item.region);
        if (in.get<bool>()) {
            assignment.start = std::make_unique<Film>(settings);
            assignment.start->restore_state(in.get_string());
        } else {
            assignment.start = std::make_unique<Film>(settings, item.first_sample);
        }
        const std::optional<Finished> finished = render_item(scene, item, std::move(assignment), tile_size, nullptr);
        mpi::send(0, mpi::Tag::Result,
                  MessageWriter()
                      .put(std::uint64_t(finished->index))
                      .put(finished->samples)
                      .put(finished->seconds)
                      .put(counters::totals().total_rays())
                      .put_string(finished->film->state())
                      .take());
    }
    mpi::send(0, mpi::Tag::Counters, encode_counters(counters::totals()));
}

}  // namespace isotrace
