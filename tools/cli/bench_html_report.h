#pragma once
// isotrace bench --report: one self-contained HTML file (inline SVG from tools/cli/svg_plot.h, no scripts, no
// network) made from the bench JSON: the machine, per-workload throughput bars, thread scaling against the ideal
// line, element-count scaling, and every figure as a table.
#include <nlohmann/json.hpp>

#include <string>

namespace isotrace::cli {

std::string bench_html_report(const nlohmann::json& report);

}  // namespace isotrace::cli
