#pragma once
// Bernstein form on [0,1] and the conservative "no root here" test built on it: a polynomial is a convex
// combination of its Bernstein coefficients on [0,1], so if they all share one strict sign so does the polynomial.
#include <array>
#include <bit>
#include <limits>

#include "geometry/polynomial/polynomial.h"
#include "renderer/math/double4.h"

namespace isotrace {

struct BernsteinCoefficients {
    int degree = 0;
    std::array<double, kMaxPolynomialDegree + 1> values{};
    // Bound on the rounding error of each value: a coefficient whose |value| is not above it has no trusted sign.
    std::array<double, kMaxPolynomialDegree + 1> error_bounds{};
};

// bₖ = Σᵢ₌₀ᵏ C(k,i)/C(n,i)·aᵢ for the polynomial Σ aᵢuⁱ of degree n. The weights are ≤ 1 and exact ratios of
// small integers, so the conversion is well conditioned for the degrees used here (≤ kMaxPolynomialDegree).
BernsteinCoefficients to_bernstein(const Polynomial& on_unit_interval);

// The signs of the control polygon (the points (k/n, bₖ)) on [0,1]:
// - variations: its sign variations, or kUntrustedSign when a coefficient is zero or too small to trust (beyond its
//   rounding bound). By Descartes' rule for the Bernstein basis the roots in the open interval (0,1), counted with
//   multiplicity, are as many as the variations or fewer by an even number:
//     0 — no root in the closed interval [0,1]: the piece can be skipped;
//     1 — exactly one root, a simple one, and p(0), p(1) have trusted opposite signs: [0,1] brackets it.
// - polygon_crossing: where the polygon first crosses zero, when there are variations. The polygon hugs the curve, so
//   on a piece with one simple root this is a start for Newton's method closer than the secant through the piece's
//   ends (blobs_1k: 3.59 → 3.12 steps per solved piece; bernstein_test).
// `coefficient_error` bounds Σᵢ|Δaᵢ|, the error the caller's coefficients already carry (it bounds each Bernstein
// value's error too, as the conversion weights are ≤ 1).
constexpr int kUntrustedSign = -1;
struct BernsteinSigns {
    int variations = 0;
    double polygon_crossing = 0.5;  // in [0, 1] (0 or 1 only by rounding), when variations ≥ 1
};
inline BernsteinSigns bernstein_signs(const Polynomial& on_unit_interval, double coefficient_error = 0);

namespace bernstein_detail {

constexpr int kSize = kMaxPolynomialDegree + 1;

constexpr auto kBinomials = [] {
    std::array<std::array<double, kSize>, kSize> table{};
    for (int n = 0; n <= kMaxPolynomialDegree; ++n) {
        table[n][0] = 1;
        for (int k = 1; k <= n; ++k) table[n][k] = table[n - 1][k - 1] + (k < n ? table[n - 1][k] : 0);
    }
    return table;
}();

// The conversion weight C(k,i)/C(n,i) of coefficient i in Bernstein value k, per degree n, as columns: kColumns[n][i]
// holds it for every k (0 where k < i or k > n), in lanes of four.
constexpr auto kColumns = [] {
    std::array<std::array<std::array<double, 4 * kCoefficientQuads>, kSize>, kSize> table{};
    for (int n = 0; n <= kMaxPolynomialDegree; ++n)
        for (int i = 0; i <= n; ++i)
            for (int k = i; k <= n; ++k) table[n][i][k] = kBinomials[k][i] / kBinomials[n][i];
    return table;
}();

// Each value is a sum of k+1 products with rounded weights; 2n+4 ulps of the absolute sum covers it.
constexpr double relative_conversion_error(int n) { return (2 * n + 4) * std::numeric_limits<double>::epsilon(); }

// Every Bernstein value bₖ of the degree-n polynomial p and the Σᵢ|C(k,i)/C(n,i)·aᵢ| of its terms, kQuadsUsed lanes
// of four (4·kQuadsUsed > n): coefficient by coefficient, each added to every value it enters, in ascending i as a
// value's own sum would run (so the same bits as summing value by value).
template <int kQuadsUsed>
void bernstein_values(const Polynomial& p, int n, Double4 (&value)[kQuadsUsed], Double4 (&magnitude)[kQuadsUsed]) {
    for (int q = 0; q < kQuadsUsed; ++q) value[q] = magnitude[q] = Double4{};
    for (int i = 0; i <= n; ++i) {
        const double a = p[i];
        for (int q = 0; q < kQuadsUsed; ++q) {
            const std::int64_t first = 4 * q;
            // Values before i (and beyond n) take nothing from aᵢ: masked, so an infinite aᵢ cannot reach them.
            const Mask4 enters = Mask4{first, first + 1, first + 2, first + 3} >= std::int64_t(i);
            const Double4 term = select(enters, load4(kColumns[std::size_t(n)][std::size_t(i)].data() + first) * a,
                                        Double4{});
            value[q] += term;
            magnitude[q] += abs4(term);
        }
    }
}

template <int kQuadsUsed>
BernsteinSigns signs(const Polynomial& p, double coefficient_error) {
    const int n = p.degree();
    Double4 value[kQuadsUsed], magnitude[kQuadsUsed];
    bernstein_values(p, n, value, magnitude);
    const double relative_error = relative_conversion_error(n);
    unsigned untrusted = 0, positive = 0;
    for (int q = 0; q < kQuadsUsed; ++q) {
        untrusted |= mask_bits(abs4(value[q]) <= relative_error * magnitude[q] + coefficient_error) << (4 * q);
        positive |= mask_bits(value[q] > 0.0) << (4 * q);
    }
    const unsigned values = (2u << n) - 1;  // b₀ … bₙ
    if ((untrusted & values) != 0) return {kUntrustedSign};
    const unsigned changes = (positive ^ (positive >> 1)) & (values >> 1);  // bit k: bₖ and bₖ₊₁ differ in sign
    if (changes == 0) return {0};
    alignas(32) double b[4 * kQuadsUsed];
    for (int q = 0; q < kQuadsUsed; ++q) store4(b + 4 * q, value[q]);
    const int k = std::countr_zero(changes);
    return {std::popcount(changes), (k + b[k] / (b[k] - b[k + 1])) / n};
}

}  // namespace bernstein_detail

inline BernsteinSigns bernstein_signs(const Polynomial& on_unit_interval, double coefficient_error) {
    // All values at once in lanes (the blob march's pieces are of degree ≤ 6: two lanes of four). Inline, so that
    // the AVX2 build of the blob cell queries has its own (blob_cell_queries.h).
    return with_coefficient_quads(on_unit_interval.degree(), [&]<int kQuads>() {
        return bernstein_detail::signs<kQuads>(on_unit_interval, coefficient_error);
    });
}

}  // namespace isotrace
