#pragma once
// Bernstein form on [0,1] and the conservative "no root here" test built on it: a polynomial is a convex
// combination of its Bernstein coefficients on [0,1], so if they all share one strict sign so does the polynomial.
#include <array>

#include "geometry/polynomial/polynomial.h"

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

// The sign variations of the control polygon on [0,1], or kUntrustedSign when a coefficient is zero or too small
// to trust (beyond its rounding bound). By Descartes' rule for the Bernstein basis the roots in the open interval
// (0,1), counted with multiplicity, are as many as the variations or fewer by an even number:
//   0 — no root in the closed interval [0,1]: the piece can be skipped;
//   1 — exactly one root, a simple one, and p(0), p(1) have trusted opposite signs: [0,1] brackets it.
// `coefficient_error` bounds Σᵢ|Δaᵢ|, the error the caller's coefficients already carry (it bounds each Bernstein
// value's error too, as the conversion weights are ≤ 1).
constexpr int kUntrustedSign = -1;
int bernstein_sign_variations(const Polynomial& on_unit_interval, double coefficient_error = 0);

}  // namespace isotrace
