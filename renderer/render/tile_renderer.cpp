#include "renderer/render/tile_renderer.h"

#include <tbb/blocked_range.h>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include "renderer/core/parallel_for.h"
#include "renderer/core/render_counters.h"
#include "renderer/embree/embree_device.h"
#include "renderer/math/lanes.h"
#include "renderer/render/sample_camera_ray.h"
#include "renderer/sampling/sampler.h"

namespace isotrace {
namespace {

using Clock = std::chrono::steady_clock;

// Why the tiles were told to stop taking samples. Cancel and Deadline end the render; Checkpoint pauses it.
enum class Stop : int { None, Checkpoint, Deadline, Cancel };

std::vector<PixelBounds> make_tiles(const PixelBounds& area, int tile_size) {
    std::vector<PixelBounds> tiles;
    for (int y = area.y0; y < area.y1; y += tile_size)
        for (int x = area.x0; x < area.x1; x += tile_size)
            tiles.push_back({x, y, std::min(x + tile_size, area.x1), std::min(y + tile_size, area.y1)});
    return tiles;
}

// The flags a tile reads before each sample: the watcher's, and the caller's cancel flag directly, so that a
// cancellation takes effect without waiting for the watcher's next tick.
struct StopFlags {
    const std::atomic<int>& stop;
    const std::atomic<bool>* cancel;
    bool raised() const {
        return stop.load(std::memory_order_relaxed) != int(Stop::None) ||
               (cancel && cancel->load(std::memory_order_relaxed));
    }
};

// How many samples the integrator traces together in this scene (mostly one).
std::size_t samples_traced_together(const LoadedScene& loaded) {
    return std::clamp<std::size_t>(loaded.integrator->samples_traced_together(*loaded.scene), 1,
                                   Integrator::kMaxSamplesTogether);
}

// Brings every pixel of `tile` up to `last` samples, continuing from the samples it already has, in sample
// order. The samples go to the integrator in groups of as many as it traces together (mostly one), a pixel's
// samples in order and the pixels in scan order, so that a group may hold the samples of several pixels. Reads the
// stop flags before each pixel's samples are queued (two relaxed loads), so even a tile at high spp stops within
// one group; samples queued but not yet traced are left untaken. Returns the samples it took.
std::int64_t render_tile(const LoadedScene& loaded, Film& film, const PixelBounds& tile, std::uint32_t last,
                         const StopFlags& flags) {
    constexpr std::size_t kGroup = Integrator::kMaxSamplesTogether;
    const std::size_t group = samples_traced_together(loaded);
    std::array<SampleStream, kGroup> streams;
    std::array<Ray, kGroup> rays;
    std::array<CameraSample, kGroup> samples;
    std::array<PrimaryHitRecord, kGroup> primary;
    std::array<Rgb, kGroup> radiance;
    std::array<std::array<int, 2>, kGroup> pixel_of;
    const bool keeps_albedo = film.keeps_hit_data();
    std::int64_t taken = 0;
    std::size_t queued = 0;
    const auto trace_queued = [&] {
        if (queued == 0) return;
        loaded.integrator->radiance_of_samples(std::span(rays.data(), queued), *loaded.scene,
                                               std::span(streams.data(), queued), std::span(primary.data(), queued),
                                               std::span(radiance.data(), queued));
        for (std::size_t i = 0; i < queued; ++i) {
            CameraSample& sample = samples[i];
            sample.radiance = radiance[i];
            sample.primary = primary[i];
            // Integrators do not know the camera: the depth AOV is filled in here from the hit position.
            if (sample.primary.hit) sample.primary.depth = loaded.camera->view_depth(sample.primary.position);
            if (!Film::holds(sample.radiance)) {  // counted and dropped, so one bad path cannot poison a pixel
                counters::count_nan_sample();
                sample.radiance = Rgb();
            }
            film.add_sample(pixel_of[i][0], pixel_of[i][1], sample);
        }
        taken += std::int64_t(queued);
        queued = 0;
    };
    for (int y = tile.y0; y < tile.y1; ++y) {
        for (int x = tile.x0; x < tile.x1; ++x) {
            for (std::uint32_t first = film.sample_count(x, y); first < last;) {
                if (flags.raised()) return taken;
                const std::size_t count = std::min<std::size_t>(group - queued, last - first);
                const std::span<SampleStream> added(streams.data() + queued, count);
                const PixelSampleContext pixel = loaded.sampler->context({std::uint32_t(x), std::uint32_t(y), first});
                for (std::size_t i = 0; i < count; ++i)
                    added[i] = SampleStream::of_context(*loaded.sampler, pixel.of_sample(first + std::uint32_t(i)));
                SampleStream::fill_caches(added);  // the camera's block, for all of the pixel's at once
                for (std::size_t i = queued; i < queued + count; ++i) {
                    const SampleCameraRay camera = sample_camera_ray(loaded, x, y, streams[i]);
                    const FilterSample& offset = camera.offset;
                    rays[i] = camera.ray;
                    samples[i] = CameraSample{};
                    samples[i].filter_weight = offset.weight;
                    samples[i].offset_squared = offset.dx * offset.dx + offset.dy * offset.dy;
                    primary[i] = PrimaryHitRecord{};
                    primary[i].keeps_albedo = keeps_albedo;
                    pixel_of[i] = {x, y};
                }
                queued += count;
                first += std::uint32_t(count);
                if (queued == group) trace_queued();
            }
        }
    }
    trace_queued();
    return taken;
}

// A thread that, every few milliseconds, turns the cancel flag, the time budget and the checkpoint interval
// into the one stop flag the tiles read, and reports progress about 5 times a second.
class RenderWatcher {
public:
    RenderWatcher(const RenderOptions& options, std::atomic<int>& stop, std::function<double()> elapsed,
                  std::function<RenderProgress()> snapshot)
        : options_(options), stop_(stop), elapsed_(std::move(elapsed)), snapshot_(std::move(snapshot)) {
        next_checkpoint_ = options_.checkpoint_interval_seconds.value_or(0);
        thread_ = std::thread([this] { run(); });
    }
    ~RenderWatcher() {
        {
            std::lock_guard lock(mutex_);
            done_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }

    // Called after a checkpoint was written: lifts the pause (unless something more important came meanwhile).
    void checkpoint_written() {
        next_checkpoint_ = elapsed_() + *options_.checkpoint_interval_seconds;
        int expected = int(Stop::Checkpoint);
        stop_.compare_exchange_strong(expected, int(Stop::None));
    }

    // The checks the thread makes, also made by the rendering thread before each pass.
    void check() {
        if (options_.cancel && options_.cancel->load(std::memory_order_relaxed)) {
            stop_ = int(Stop::Cancel);
            return;
        }
        const double now = elapsed_();
        if (options_.time_budget_seconds && now >= *options_.time_budget_seconds) {
            raise(Stop::Deadline);
            return;
        }
        if (options_.on_checkpoint && options_.checkpoint_interval_seconds && now >= next_checkpoint_.load())
            raise(Stop::Checkpoint);
    }

private:
    void raise(Stop reason) {  // a stronger reason replaces a weaker one, never the other way round
        int current = stop_.load();
        while (current < int(reason) && !stop_.compare_exchange_weak(current, int(reason))) {
        }
    }

    void run() {
        constexpr auto kTick = std::chrono::milliseconds(10);
        constexpr int kTicksPerReport = 20;
        std::unique_lock lock(mutex_);
        for (int tick = 1; !wake_.wait_for(lock, kTick, [this] { return done_; }); ++tick) {
            check();
            if (options_.on_started && tick == 1) options_.on_started();
            if (options_.on_progress && tick % kTicksPerReport == 0) options_.on_progress(snapshot_());
        }
    }

    const RenderOptions& options_;
    std::atomic<int>& stop_;
    std::function<double()> elapsed_;
    std::function<RenderProgress()> snapshot_;
    std::atomic<double> next_checkpoint_{0};
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;
    std::thread thread_;
};

}  // namespace

RenderResult render_scene(const LoadedScene& loaded, const RenderOptions& options, std::unique_ptr<Film> film) {
    RenderResult result;
    result.film = film ? std::move(film) : std::make_unique<Film>(loaded.film);
    const std::vector<PixelBounds> tiles = make_tiles(result.film->bounds(), std::max(1, options.tile_size));
    const std::int64_t pixels = result.film->bounds().area();
    const auto start = Clock::now();
    const auto elapsed = [start] { return std::chrono::duration<double>(Clock::now() - start).count(); };

    const SampleCountRange initial = result.film->sample_count_range();
    std::atomic<std::int64_t> samples_taken{0};  // in this call
    std::atomic<int> completed_spp{int(initial.min)};  // readable from the watcher thread
    const double budget = options.time_budget_seconds.value_or(0);
    std::atomic<int> stop{int(Stop::None)};
    const StopFlags flags{stop, options.cancel};

    const auto snapshot = [&] {
        RenderProgress progress;
        progress.elapsed_seconds = elapsed();
        progress.time_budget_seconds = options.time_budget_seconds;
        const double planned = double(pixels) * options.spp;
        const double sample_fraction = std::min(
            1.0, (double(initial.total) + double(samples_taken.load())) / std::max(1.0, planned));
        progress.fraction = options.time_budget_seconds
                                ? std::max(sample_fraction, std::min(1.0, progress.elapsed_seconds / budget))
                                : sample_fraction;
        if (progress.fraction > 0)
            progress.eta_seconds = progress.elapsed_seconds * (1 - progress.fraction) / progress.fraction;
        progress.rays = counters::totals().total_rays();
        progress.completed_spp = completed_spp.load();
        return progress;
    };
    std::optional<RenderWatcher> watch(std::in_place, options, stop, elapsed, snapshot);
    RenderWatcher& watcher = *watch;

    const int first_pass_end = int(std::bit_ceil(std::min<std::size_t>(samples_traced_together(loaded), kLanes)));
    std::uint32_t last_pass_end_seen = 0;
    for (;;) {
        const SampleCountRange now = result.film->sample_count_range();
        const int completed = int(now.min);
        completed_spp = completed;
        if (options.stop_at_pass_end && now.min == now.max && std::has_single_bit(now.min) &&
            now.min != last_pass_end_seen) {
            last_pass_end_seen = now.min;
            if (options.stop_at_pass_end(*result.film)) {
                result.stopped_at_pass_end = true;
                break;
            }
        }
        if (completed >= options.spp) break;
        watcher.check();
        if (stop == int(Stop::Checkpoint)) {
            options.on_checkpoint(*result.film);
            ++result.checkpoints;
            watcher.checkpoint_written();
            continue;
        }
        if (stop != int(Stop::None)) break;
        // Passes end at the powers of two (1, 2, 4, 8, ...): sizes double so early passes give a quick preview,
        // and a film left at another count (a pass shrunk by a time budget, then resumed) is brought back onto
        // the same boundaries that stop_at_pass_end is asked at. An integrator that traces samples together
        // gets a first pass of a packet's lanes of each pixel's samples (8), so that a pixel's camera rays, which
        // are near-parallel, make a packet of their own (docs/decisions.md, "Passes that fill the lanes"). Under a time
        // budget the next pass is shrunk to what the measured speed says still fits, so that most budgets end on a
        // whole pass. (The budget is hard either way: a pass that overruns is stopped within a group.)
        const int next_boundary =
            std::max(first_pass_end, int(std::bit_floor(std::uint32_t(completed))) * 2);
        int pass_spp = std::min(options.spp - completed, next_boundary - completed);
        if (options.time_budget_seconds && samples_taken > 0) {
            const double seconds_per_spp = elapsed() * double(pixels) / double(samples_taken.load());
            const double fits = (budget - elapsed()) / seconds_per_spp;
            if (!(fits >= 1)) break;
            pass_spp = int(std::min(double(pass_spp), fits));  // compare as doubles: fits may exceed INT_MAX
        }
        const std::uint32_t last = std::uint32_t(completed + pass_spp);
        parallel_for(
            tbb::blocked_range<std::size_t>(0, tiles.size(), 1),
            [&](const tbb::blocked_range<std::size_t>& range) {
                enable_flush_to_zero();
                for (std::size_t t = range.begin(); t != range.end(); ++t)
                    samples_taken += render_tile(loaded, *result.film, tiles[t], last, flags);
            },
            tbb::simple_partitioner());
        ++result.passes;
    }
    watcher.check();  // a cancellation seen by the tiles but not yet by the watcher
    watch.reset();    // no more reports from the watcher thread
    const SampleCountRange counts = result.film->sample_count_range();
    result.completed_spp = int(counts.min);
    result.max_spp = int(counts.max);
    result.partial = counts.min != counts.max;
    result.cancelled = stop == int(Stop::Cancel);
    result.out_of_time = options.time_budget_seconds && result.completed_spp < options.spp && !result.cancelled &&
                         !result.stopped_at_pass_end;
    result.seconds = elapsed();
    if (options.on_progress) {  // the last report: 100 % unless the render was cancelled
        RenderProgress last = snapshot();
        last.completed_spp = result.completed_spp;
        if (!result.cancelled) {
            last.fraction = 1;
            last.eta_seconds = 0;
        }
        options.on_progress(last);
    }
    return result;
}

}  // namespace isotrace
