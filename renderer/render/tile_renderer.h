#pragma once
// Renders a loaded scene: progressive passes over TBB-scheduled tiles, with sample-count and hard time budgets,
// cooperative cancellation (Ctrl-C, SIGTERM) and pauses for checkpoints. Every stop is sample-granular: a
// watcher thread raises one flag that the tiles read before each sample. A pixel's samples are always taken in
// index order, continuing from the sample count the film already holds, so the image depends only on each pixel's
// final sample count — not on thread count, tile size, when the render stopped, or how often it was resumed.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "renderer/film/film.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace {

struct RenderProgress {
    double fraction = 0;           // of the planned samples (time budget: of the time)
    double elapsed_seconds = 0;
    double eta_seconds = -1;       // < 0 when unknown
    std::uint64_t rays = 0;
    int completed_spp = 0;         // samples every pixel has
    std::optional<double> time_budget_seconds;
};

struct RenderOptions {
    int tile_size = 32;
    int spp = 16;                                  // sample budget per pixel
    std::optional<double> time_budget_seconds;     // hard: the render stops within a sample of running out
    const std::atomic<bool>* cancel = nullptr;     // set asynchronously to stop within a sample
    std::function<void(const RenderProgress&)> on_progress;  // called about 5 times a second from one thread
    // Called once, from the same thread, when the render has run for a moment (its worker threads have started):
    // for work meant to overlap the render without holding up its start (creating a thread waits while a library
    // is being loaded, so loading one earlier would delay the workers).
    std::function<void()> on_started;
    // Called from the rendering thread with the film in a consistent state (no sample in flight) every
    // checkpoint_interval_seconds of rendering; the render waits while it runs.
    std::optional<double> checkpoint_interval_seconds;
    std::function<void(const Film&)> on_checkpoint;
    // Called on the rendering thread at every pass boundary where all pixels have the same power-of-two sample
    // count (passes end at 1, 2, 4, 8, ... samples; the first at the number of samples the integrator traces
    // together, 8 for the path tracer), at most once per count; returning true ends the render.
    // What it sees depends only on the image at those counts, never on timing or threads, so a stop it decides
    // is reproducible (isotrace render --target-error).
    std::function<bool(const Film&)> stop_at_pass_end;
};

struct RenderResult {
    std::unique_ptr<Film> film;
    int completed_spp = 0;   // samples every pixel received
    int max_spp = 0;         // samples the most-sampled pixel received
    bool partial = false;    // stopped mid-pass: pixels have between completed_spp and max_spp samples
    bool cancelled = false;
    bool out_of_time = false;  // the time budget ended the render
    bool stopped_at_pass_end = false;  // stop_at_pass_end returned true
    int passes = 0;            // passes started in this call
    int checkpoints = 0;       // on_checkpoint calls
    double seconds = 0;
};

// Renders the pixels of `film` when given (a resumed checkpoint, or a region of the image for another process:
// its per-pixel sample counts say where each pixel goes on); otherwise starts a new film of the scene's crop.
RenderResult render_scene(const LoadedScene& scene, const RenderOptions& options, std::unique_ptr<Film> film = {});

}  // namespace isotrace
