#include "renderer/render/tile_renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include "renderer/core/render_counters.h"
#include "renderer/embree/embree_device.h"
#include "renderer/sampling/sampler.h"

namespace isotrace {
namespace {

using Clock = std::chrono::steady_clock;

std::vector<PixelBounds> make_tiles(const PixelBounds& area, int tile_size) {
    std::vector<PixelBounds> tiles;
    for (int y = area.y0; y < area.y1; y += tile_size)
        for (int x = area.x0; x < area.x1; x += tile_size)
            tiles.push_back({x, y, std::min(x + tile_size, area.x1), std::min(y + tile_size, area.y1)});
    return tiles;
}

// Takes samples [first, last) of every pixel of `tile`, in sample order per pixel. Checks for cancellation
// before each row (a tile at high spp may take seconds); returns false if it stopped early.
template <class CancelCheck>
bool render_tile(const LoadedScene& loaded, Film& film, const PixelBounds& tile, int first, int last,
                 const CancelCheck& cancelled) {
    for (int y = tile.y0; y < tile.y1; ++y) {
        if (cancelled()) return false;
        for (int x = tile.x0; x < tile.x1; ++x) {
            for (int s = first; s < last; ++s) {
                SampleStream samples(*loaded.sampler, {std::uint32_t(x), std::uint32_t(y), std::uint32_t(s)});
                const FilterSample offset = loaded.filter->sample(samples.next_2d());
                const Ray ray = loaded.camera->generate_ray(float(x) + 0.5f + offset.dx, float(y) + 0.5f + offset.dy,
                                                            samples.next_2d());
                CameraSample sample;
                sample.filter_weight = offset.weight;
                sample.offset_squared = offset.dx * offset.dx + offset.dy * offset.dy;
                sample.radiance = loaded.integrator->radiance(ray, *loaded.scene, samples, sample.primary);
                // Integrators do not know the camera: the depth AOV is filled in here from the hit position.
                if (sample.primary.hit) sample.primary.depth = loaded.camera->view_depth(sample.primary.position);
                if (!sample.radiance.is_finite()) {  // counted and dropped, so one bad path cannot poison a pixel
                    counters::count_nan_sample();
                    sample.radiance = Rgb();
                }
                film.add_sample(x, y, sample);
            }
        }
    }
    return true;
}

// Reports progress from its own thread while the render runs.
class ProgressReporter {
public:
    ProgressReporter(const RenderOptions& options, std::function<RenderProgress()> snapshot)
        : options_(options), snapshot_(std::move(snapshot)) {
        if (options_.on_progress) thread_ = std::thread([this] { run(); });
    }
    ~ProgressReporter() {
        {
            std::lock_guard lock(mutex_);
            done_ = true;
        }
        wake_.notify_all();
        if (thread_.joinable()) thread_.join();
    }

private:
    void run() {
        std::unique_lock lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::milliseconds(200), [this] { return done_; }))
            options_.on_progress(snapshot_());
    }

    const RenderOptions& options_;
    std::function<RenderProgress()> snapshot_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;
    std::thread thread_;
};

}  // namespace

RenderResult render_scene(const LoadedScene& loaded, const RenderOptions& options) {
    RenderResult result;
    result.film = std::make_unique<Film>(loaded.film);
    const std::vector<PixelBounds> tiles = make_tiles(loaded.film.crop, std::max(1, options.tile_size));
    const std::int64_t pixels = loaded.film.crop.area();
    const auto start = Clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

    std::atomic<std::int64_t> pixel_samples_done{0};
    std::atomic<int> completed_spp{0};  // result.completed_spp, readable from the progress thread
    const double budget = options.time_budget_seconds.value_or(0);
    const auto cancelled = [&] { return options.cancel && options.cancel->load(std::memory_order_relaxed); };

    ProgressReporter reporter(options, [&] {
        RenderProgress progress;
        progress.elapsed_seconds = elapsed();
        const double sample_fraction = double(pixel_samples_done.load()) / (double(pixels) * options.spp);
        progress.fraction = options.time_budget_seconds
                                ? std::max(sample_fraction, std::min(1.0, progress.elapsed_seconds / budget))
                                : sample_fraction;
        if (progress.fraction > 0)
            progress.eta_seconds = progress.elapsed_seconds * (1 - progress.fraction) / progress.fraction;
        progress.rays = counters::totals().total_rays();
        progress.completed_spp = completed_spp.load();
        return progress;
    });

    while (result.completed_spp < options.spp && !cancelled()) {
        // Pass sizes double (1, 1, 2, 4, ...) so early passes give a quick preview; under a time budget the
        // next pass is shrunk to what the measured speed says still fits.
        int pass_spp = std::min(options.spp - result.completed_spp, std::max(1, result.completed_spp));
        if (options.time_budget_seconds && result.completed_spp > 0) {
            const double per_spp = elapsed() / result.completed_spp;
            const double fits = (budget - elapsed()) / per_spp;
            if (!(fits >= 1)) break;
            pass_spp = int(std::min(double(pass_spp), fits));  // compare as doubles: fits may exceed INT_MAX
        }
        const int first = result.completed_spp, last = first + pass_spp;
        std::atomic<bool> skipped_tile{false};
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, tiles.size(), 1),
            [&](const tbb::blocked_range<std::size_t>& range) {
                enable_flush_to_zero();
                for (std::size_t t = range.begin(); t != range.end(); ++t) {
                    if (!render_tile(loaded, *result.film, tiles[t], first, last, cancelled)) {
                        skipped_tile = true;
                        continue;
                    }
                    pixel_samples_done += tiles[t].area() * pass_spp;
                }
            },
            tbb::simple_partitioner());
        ++result.passes;
        if (skipped_tile) {
            result.partial = true;
            break;
        }
        result.completed_spp = last;
        completed_spp = last;
        if (options.time_budget_seconds && elapsed() >= budget) break;
    }
    result.cancelled = cancelled();
    result.seconds = elapsed();
    return result;
}

}  // namespace isotrace
