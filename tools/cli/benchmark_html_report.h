#pragma once
// isotrace benchmark --report: one self-contained HTML page (inline SVG, no scripts, no network) made from the
// benchmark result JSON (tools/cli/benchmark_result.h): whether the outputs matched, the scores, one bar chart of
// the per-workload scores per thread count, the speed-up of all threads over one, the system and every figure.
#include <nlohmann/json.hpp>

#include <string>

namespace isotrace::cli {

std::string benchmark_html_report(const nlohmann::json& result);

}  // namespace isotrace::cli
