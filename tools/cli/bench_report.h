#pragma once
// The results of the blob direct-vs-tessellated comparison (the workload blobs/direct_vs_tessellated of isotrace
// bench) as a table for people and as JSON for scripts (schema in docs/cli.md).
#include <nlohmann/json.hpp>

#include <string>

#include "tools/cli/blob_benchmark.h"

namespace isotrace::cli {

nlohmann::json benchmark_json(const BlobBenchmarkSettings& settings, const std::vector<SceneBenchmark>& results);

std::string benchmark_table(const nlohmann::json& report);

}  // namespace isotrace::cli
