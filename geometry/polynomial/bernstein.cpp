#include "geometry/polynomial/bernstein.h"

#include <cmath>
#include <limits>
#include <utility>

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

// The k-th Bernstein coefficient of the degree-n polynomial p, and the Σ of its terms' magnitudes.
struct CoefficientAndMagnitude {
    double value, magnitude;
};
[[gnu::always_inline]] inline CoefficientAndMagnitude bernstein_coefficient(const Polynomial& p, int n, int k) {
    double value = 0, magnitude = 0;
#pragma GCC unroll 11
    for (int i = 0; i <= k; ++i) {
        const double term = kWeights[n][k][i] * p[i];
        value += term;
        magnitude += std::abs(term);
    }
    return {value, magnitude};
}

// Each value is a sum of k+1 products with rounded weights; 2n+4 ulps of the absolute sum covers it.
constexpr double relative_conversion_error(int n) { return (2 * n + 4) * std::numeric_limits<double>::epsilon(); }

}  // namespace

BernsteinCoefficients to_bernstein(const Polynomial& on_unit_interval) {
    const int n = on_unit_interval.degree();
    const double relative_error = relative_conversion_error(n);
    BernsteinCoefficients result;
    result.degree = n;
    for (int k = 0; k <= n; ++k) {
        const auto [value, magnitude] = bernstein_coefficient(on_unit_interval, n, k);
        result.values[k] = value;
        result.error_bounds[k] = relative_error * magnitude;
    }
    return result;
}

namespace {

// bernstein_sign_variations for degree kDegree, its loops unrolled (the table's rows are then constant addresses):
// a third of the instructions of the loops over a degree read at run time (callgrind). The same operations in the
// same order, so the same result.
template <int kDegree>
int sign_variations_of_degree(const Polynomial& on_unit_interval, double coefficient_error) {
    constexpr double kRelativeError = relative_conversion_error(kDegree);
    int variations = 0;
    bool previous_positive = false;
#pragma GCC unroll 11
    for (int k = 0; k <= kDegree; ++k) {
        const auto [value, magnitude] = bernstein_coefficient(on_unit_interval, kDegree, k);
        if (std::abs(value) <= kRelativeError * magnitude + coefficient_error) return kUntrustedSign;
        const bool positive = value > 0;
        if (k > 0 && positive != previous_positive) ++variations;
        previous_positive = positive;
    }
    return variations;
}

template <int... kDegrees>
constexpr auto sign_variations_by_degree(std::integer_sequence<int, kDegrees...>) {
    return std::array{&sign_variations_of_degree<kDegrees>...};
}

}  // namespace

int bernstein_sign_variations(const Polynomial& on_unit_interval, double coefficient_error) {
    // Coefficient by coefficient, stopping at the first untrusted sign: no table of all of them is built (this test
    // runs on every ray piece the elements' ranges do not settle).
    static constexpr auto kByDegree =
        sign_variations_by_degree(std::make_integer_sequence<int, kMaxPolynomialDegree + 1>());
    return kByDegree[std::size_t(on_unit_interval.degree())](on_unit_interval, coefficient_error);
}

}  // namespace isotrace
