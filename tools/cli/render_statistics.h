#pragma once
#include <nlohmann/json.hpp>

#include <string>

#include "renderer/core/render_counters.h"
#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"
#include "tools/cli/render_warnings.h"

namespace isotrace::cli {

struct PhaseTimes {
    double parse = 0, build = 0, render = 0, write = 0;
};

// End-of-render statistics as JSON (the --stats-json schema, see docs/cli.md), all of them; the peak memory is the
// process's so far.
nlohmann::json render_statistics(const LoadedScene& scene, const RenderResult& result, const CounterTotals& counts,
                                 const PhaseTimes& times, int threads, const BeautyCheck& beauty);

// How much of them render prints (--stats): a few lines of times, speed, memory and NaNs, or every counter.
enum class StatisticsDetail { None, Short, Full };

// The statistics as a human-readable block for stderr ("" for None).
std::string format_statistics(const nlohmann::json& stats, StatisticsDetail detail);

}  // namespace isotrace::cli
