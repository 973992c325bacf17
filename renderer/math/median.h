#pragma once
// The median of a list: the middle value, or the mean of the middle two (NumPy's percentile(values, 50)).
// Partial selection, not a sort: used on every pixel of an image as well as on a handful of timings.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace isotrace {

// 0 for no values.
template <class Real>
double median(std::vector<Real> values) {
    const std::size_t n = values.size(), upper = n / 2;
    if (n == 0) return 0;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(upper), values.end());
    const double high = values[upper];
    if (n % 2 == 1) return high;
    const double low = *std::max_element(values.begin(), values.begin() + std::ptrdiff_t(upper));
    return 0.5 * (low + high);
}

// The same for a braced list of numbers: median({1, 2, 3}).
inline double median(std::vector<double> values) { return median<double>(std::move(values)); }

}  // namespace isotrace
