#pragma once
// The results of the isotrace bench suite as JSON for scripts (schema in docs/cli.md) and as a table for people.
// The table and the HTML report (tools/cli/bench_html_report.h) are both made from the JSON.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "tools/cli/bench_scaling.h"
#include "tools/cli/bench_workloads.h"

namespace isotrace::cli {

// One workload: its figures per thread count, with the median and spread of the throughput and the speed-up
// and parallel efficiency relative to the first (smallest) thread count.
nlohmann::json workload_json(const WorkloadResult& result);

nlohmann::json scaling_json(const std::vector<ScalingPoint>& points);

// The per-workload table, then the thread-scaling table (with more than one thread count) and the
// element-count scaling table (when the report has one).
std::string suite_table(const nlohmann::json& report);

}  // namespace isotrace::cli
