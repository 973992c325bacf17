#pragma once
// Stratification measure of 2-D point sets in base 2, shared by the Sobol' and sampler tests.
#include <array>
#include <span>

namespace isotrace::test_support {

// The t-value of 2^m points in [0,1)^2 as a (t,m,2)-net: the smallest t such that every elementary
// interval [a/2^k, (a+1)/2^k) x [b/2^(m-t-k), (b+1)/2^(m-t-k)) holds exactly 2^t points.
// t = 0 means one point in every elementary interval of area 2^-m. Requires a power-of-two point count.
int net_t_value(std::span<const std::array<double, 2>> points);

}  // namespace isotrace::test_support
