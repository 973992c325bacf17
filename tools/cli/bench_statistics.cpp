#include "tools/cli/bench_statistics.h"

#include <algorithm>
#include <cmath>

namespace isotrace::cli {
namespace {

// The p-quantile (0 ≤ p ≤ 1) of sorted values, interpolating linearly between neighbours.
double quantile_of_sorted(const std::vector<double>& sorted, double p) {
    const double position = p * double(sorted.size() - 1);
    const std::size_t below = std::size_t(std::floor(position));
    const std::size_t above = std::min(below + 1, sorted.size() - 1);
    return sorted[below] + (position - double(below)) * (sorted[above] - sorted[below]);
}

}  // namespace

Spread spread_of(std::vector<double> values) {
    if (values.empty()) return {};
    std::sort(values.begin(), values.end());
    return {values.front(), quantile_of_sorted(values, 0.25), quantile_of_sorted(values, 0.5),
            quantile_of_sorted(values, 0.75), values.back()};
}

double speedup(double throughput, double base_throughput) {
    return base_throughput > 0 ? throughput / base_throughput : 0;
}

double parallel_efficiency(double speedup, int threads, int base_threads) {
    return threads > 0 && base_threads > 0 ? speedup * double(base_threads) / double(threads) : 0;
}

}  // namespace isotrace::cli
