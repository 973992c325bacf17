#pragma once
// The statistics isotrace bench reports: the median and spread of repeated runs, and thread scaling.
#include <vector>

#include "renderer/math/median.h"

namespace isotrace::cli {

using isotrace::median;  // renderer/math/median.h

// Five-number summary of repeated measurements; quartiles by linear interpolation between order statistics
// (the "type 7" rule of R and NumPy's default), so that one run gives min = q1 = median = q3 = max.
struct Spread {
    double min = 0, q1 = 0, median = 0, q3 = 0, max = 0;
};
Spread spread_of(std::vector<double> values);  // all zeros for no values

// Throughput on `threads` threads over throughput on `base_threads`, and that speed-up over the ideal
// threads / base_threads (1 = perfect scaling). 0 when the base throughput is not positive.
double speedup(double throughput, double base_throughput);
double parallel_efficiency(double speedup, int threads, int base_threads);

}  // namespace isotrace::cli
