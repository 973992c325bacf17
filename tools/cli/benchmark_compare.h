#pragma once
// isotrace benchmark compare A.json B.json: how much faster B is than A, per workload and thread count and
// overall, each ratio with a 95 % confidence interval from the spread of the units' times.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace isotrace::cli {

// A benchmark result file; throws InputError naming `path` when it cannot be read, is not JSON, is not a result of
// this result format or is of another suite.
nlohmann::json read_benchmark_result(const std::string& path);

struct RatioInterval {
    double ratio = 0, low = 0, high = 0;
};

// The ratio of B's mean rate (units per second, from its units' seconds) to A's, and its 95 % confidence interval:
// normal on the log of the ratio, with the delta method's standard error sqrt(cv_a^2 / n_a + cv_b^2 / n_b) (cv: the
// rates' coefficient of variation). One unit on a side gives no spread for it. ratio = 0 when a side has no units.
RatioInterval rate_ratio(const std::vector<double>& a_seconds, const std::vector<double>& b_seconds);

// The comparison table: per workload and thread count B/A with its interval, then the overall geometric mean.
// Throws InputError when the two results are of different suites (read_benchmark_result checks each).
std::string benchmark_comparison(const nlohmann::json& a, const nlohmann::json& b);

}  // namespace isotrace::cli
