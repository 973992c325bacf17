#pragma once
// Renders a loaded scene: progressive passes over TBB-scheduled tiles, with sample-count and time budgets
// and cooperative cancellation (Ctrl-C). Results do not depend on thread count or tile size.
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
    int completed_spp = 0;
};

struct RenderOptions {
    int tile_size = 32;
    int spp = 16;                                  // sample budget per pixel
    std::optional<double> time_budget_seconds;     // stop after the pass in which the budget runs out
    const std::atomic<bool>* cancel = nullptr;     // set asynchronously to stop at the next tile
    std::function<void(const RenderProgress&)> on_progress;  // called about 5 times a second from one thread
};

struct RenderResult {
    std::unique_ptr<Film> film;
    int completed_spp = 0;   // samples every pixel received
    bool partial = false;    // cancelled mid-pass: some pixels have more samples than completed_spp
    bool cancelled = false;
    int passes = 0;
    double seconds = 0;
};

RenderResult render_scene(const LoadedScene& scene, const RenderOptions& options);

}  // namespace isotrace
