#pragma once
// Test helpers for the polynomial toolkit: a brute-force long-double root oracle and random polynomials with
// known roots.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <vector>

#include "geometry/polynomial/polynomial.h"
#include "geometry/polynomial/polynomial_root.h"

namespace isotrace {

// leading · ∏(t − rᵢ). Throws std::length_error for more than kMaxPolynomialDegree roots.
inline Polynomial polynomial_from_roots(std::span<const double> roots, double leading = 1) {
    Polynomial product{leading};
    for (double root : roots) product = product * Polynomial{-root, 1};
    return product;
}

inline long double evaluate_long_double(const Polynomial& p, long double t) {
    long double value = p[p.degree()];
    for (int i = p.degree() - 1; i >= 0; --i) value = value * t + p[i];
    return value;
}

// Sign-change roots of p (its double coefficients taken as exact) in [a, b]: `samples` equal steps evaluated in
// long double, each sign change bisected to long-double precision, samples that are exactly zero taken as roots.
// Roots closer than one step, and roots without a sign change, are invisible to it by design.
inline std::vector<double> oracle_roots(const Polynomial& p, double a, double b, int samples = 4096) {
    std::vector<double> roots;
    const long double step = ((long double)b - a) / samples;
    long double previous_t = a, previous_value = evaluate_long_double(p, a);
    if (previous_value == 0) roots.push_back(a);
    for (int i = 1; i <= samples; ++i) {
        const long double t = i == samples ? (long double)b : a + i * step;
        const long double value = evaluate_long_double(p, t);
        if (value == 0) {
            roots.push_back(double(t));
        } else if (previous_value != 0 && (value < 0) != (previous_value < 0)) {
            long double lo = previous_t, hi = t;
            for (int k = 0; k < 80; ++k) {
                const long double mid = 0.5L * (lo + hi);
                ((evaluate_long_double(p, mid) < 0) == (previous_value < 0) ? lo : hi) = mid;
            }
            roots.push_back(double(0.5L * (lo + hi)));
        }
        previous_t = t;
        previous_value = value;
    }
    return roots;
}

inline std::vector<double> root_values(const PolynomialRoots& roots) {
    std::vector<double> values;
    for (const PolynomialRoot& root : roots) values.push_back(root.t);
    return values;
}

// Same count, and each root within tolerance·max(1, |expected|) of its partner in ascending order, widened by
// 2·(evaluation rounding bound)/|p'|: no double-precision solver can locate a simple root of p better than that.
inline void expect_same_roots(const Polynomial& p, const std::vector<double>& found, const std::vector<double>& expected,
                              double tolerance) {
    ASSERT_EQ(found.size(), expected.size()) << ::testing::PrintToString(found) << " vs "
                                             << ::testing::PrintToString(expected);
    const Polynomial slope = p.derivative();
    for (std::size_t i = 0; i < found.size(); ++i) {
        const double rounding_limit = 2 * p.evaluation_error_bound(expected[i]) / std::abs(slope.evaluate(expected[i]));
        EXPECT_NEAR(found[i], expected[i], tolerance * std::max(1.0, std::abs(expected[i])) + rounding_limit)
            << "root " << i;
    }
}

struct RandomPolynomial {
    Polynomial polynomial;
    std::vector<double> real_roots;  // ascending, all of them (inside and outside any interval)
};

// leading · ∏(t − rᵢ) · ∏((t − cⱼ)² + sⱼ²) of total degree `degree`: real roots uniform in [lo, hi], at least
// `min_separation` apart and from the ends 0 and 1 (so the oracle resolves them), complex pairs at least 0.05
// off the real axis (so no near-tangency hides in them).
inline RandomPolynomial random_polynomial(std::mt19937_64& random, int degree, double lo = -0.5, double hi = 1.5,
                                          double min_separation = 1e-3) {
    std::uniform_real_distribution<double> uniform(0, 1);
    RandomPolynomial result{Polynomial{(uniform(random) < 0.5 ? -1 : 1) * (0.5 + uniform(random))}, {}};
    const int complex_pairs = std::uniform_int_distribution<int>(0, degree / 2)(random);
    for (int j = 0; j < complex_pairs; ++j) {
        const double centre = lo + (hi - lo) * uniform(random), spread = 0.05 + uniform(random);
        result.polynomial = result.polynomial * Polynomial{centre * centre + spread * spread, -2 * centre, 1};
    }
    while (static_cast<int>(result.real_roots.size()) < degree - 2 * complex_pairs) {
        const double root = lo + (hi - lo) * uniform(random);
        const auto too_close = [&](double other) { return std::abs(root - other) < min_separation; };
        if (too_close(0) || too_close(1) || std::any_of(result.real_roots.begin(), result.real_roots.end(), too_close))
            continue;
        result.real_roots.push_back(root);
        result.polynomial = result.polynomial * Polynomial{-root, 1};
    }
    std::sort(result.real_roots.begin(), result.real_roots.end());
    return result;
}

inline std::vector<double> roots_inside(const std::vector<double>& roots, double a, double b) {
    std::vector<double> inside;
    std::copy_if(roots.begin(), roots.end(), std::back_inserter(inside), [&](double r) { return r >= a && r <= b; });
    return inside;
}

}  // namespace isotrace
