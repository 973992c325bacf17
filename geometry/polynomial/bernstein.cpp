#include "geometry/polynomial/bernstein.h"

#include <cmath>
#include <limits>

namespace isotrace {
namespace {

constexpr int kSize = kMaxPolynomialDegree + 1;

constexpr auto kBinomials = [] {
    std::array<std::array<double, kSize>, kSize> table{};
    for (int n = 0; n <= kMaxPolynomialDegree; ++n) {
        table[n][0] = 1;
        for (int k = 1; k <= n; ++k) table[n][k] = table[n - 1][k - 1] + (k < n ? table[n - 1][k] : 0);
    }
    return table;
}();

// The conversion weights C(k,i)/C(n,i) per degree n, computed once (the skip test runs for every ray piece).
constexpr auto kWeights = [] {
    std::array<std::array<std::array<double, kSize>, kSize>, kSize> table{};
    for (int n = 0; n <= kMaxPolynomialDegree; ++n)
        for (int k = 0; k <= n; ++k)
            for (int i = 0; i <= k; ++i) table[n][k][i] = kBinomials[k][i] / kBinomials[n][i];
    return table;
}();

}  // namespace

BernsteinCoefficients to_bernstein(const Polynomial& on_unit_interval) {
    const int n = on_unit_interval.degree();
    // Each value is a sum of k+1 products with rounded weights; 2n+4 ulps of the absolute sum covers it.
    const double relative_error = (2 * n + 4) * std::numeric_limits<double>::epsilon();
    BernsteinCoefficients result;
    result.degree = n;
    for (int k = 0; k <= n; ++k) {
        double value = 0, magnitude = 0;
        for (int i = 0; i <= k; ++i) {
            const double term = kWeights[n][k][i] * on_unit_interval[i];
            value += term;
            magnitude += std::abs(term);
        }
        result.values[k] = value;
        result.error_bounds[k] = relative_error * magnitude;
    }
    return result;
}

int bernstein_sign_variations(const Polynomial& on_unit_interval, double coefficient_error) {
    const BernsteinCoefficients bernstein = to_bernstein(on_unit_interval);
    int variations = 0;
    for (int k = 0; k <= bernstein.degree; ++k) {
        if (std::abs(bernstein.values[k]) <= bernstein.error_bounds[k] + coefficient_error) return kUntrustedSign;
        if (k > 0 && (bernstein.values[k] > 0) != (bernstein.values[k - 1] > 0)) ++variations;
    }
    return variations;
}

}  // namespace isotrace
