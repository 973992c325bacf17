#pragma once
#include <nlohmann/json.hpp>

#include <string>

#include "renderer/core/render_counters.h"
#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace::cli {

struct PhaseTimes {
    double parse = 0, build = 0, render = 0, write = 0;
};

// End-of-render statistics as JSON (the --stats-json schema, see docs/cli.md).
nlohmann::json render_statistics(const LoadedScene& scene, const RenderResult& result, const CounterTotals& counts,
                                 const PhaseTimes& times, int threads);

// The same statistics as a human-readable block for stderr.
std::string format_statistics(const nlohmann::json& stats);

}  // namespace isotrace::cli
