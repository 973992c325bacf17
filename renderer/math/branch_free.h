#pragma once
// Minimum, maximum and masking of doubles without a branch. GCC 12 compiles std::min / std::max and `c ? v : 0` on
// doubles to compare-and-jump, which costs a misprediction whenever the outcome is data (the ranges of a blob
// sweep's elements: which end of a piece is nearer, whether a point lies inside a support). On x86-64 these are
// one SSE2 instruction each; elsewhere they fall back to the standard forms.
#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace isotrace {

#if defined(__SSE2__)
namespace branch_free_detail {
// One SSE2 operation on the low lanes of a and b.
template <class Operation>
double on_low_lanes(Operation operation, double a, double b) {
    return _mm_cvtsd_f64(operation(_mm_set_sd(a), _mm_set_sd(b)));
}
}  // namespace branch_free_detail
#endif

// a < b ? a : b, as std::min(b, a) (the same value for any a, b that are not NaN).
inline double min_branch_free(double a, double b) {
#if defined(__SSE2__)
    return branch_free_detail::on_low_lanes([](__m128d x, __m128d y) { return _mm_min_sd(x, y); }, a, b);
#else
    return std::min(b, a);
#endif
}

// a > b ? a : b, as std::max(b, a).
inline double max_branch_free(double a, double b) {
#if defined(__SSE2__)
    return branch_free_detail::on_low_lanes([](__m128d x, __m128d y) { return _mm_max_sd(x, y); }, a, b);
#else
    return std::max(b, a);
#endif
}

// a < b ? value : +0.
inline double zero_unless_less(double value, double a, double b) {
#if defined(__SSE2__)
    const double mask = branch_free_detail::on_low_lanes([](__m128d x, __m128d y) { return _mm_cmplt_sd(x, y); }, a, b);
    return branch_free_detail::on_low_lanes([](__m128d x, __m128d y) { return _mm_and_pd(x, y); }, mask, value);
#else
    return a < b ? value : 0.0;
#endif
}

}  // namespace isotrace
