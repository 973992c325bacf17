// refine_bracketed_root: the root of random polynomials (degrees 1 to 10, Estrin's evaluation up to 7 and Horner's
// beyond) in brackets around one simple root, against the known roots, and the step that rounds to nothing.
#include "geometry/polynomial/bracketed_root.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "geometry/polynomial/polynomial_test_support.h"

namespace isotrace {
namespace {

TEST(BracketedRoot, FindsTheOneRootOfRandomPolynomialsBetweenTheirNeighbours) {
    std::mt19937_64 random(17);
    int brackets = 0;
    for (int degree = 1; degree <= 10; ++degree) {
        for (int trial = 0; trial < 200; ++trial) {
            const RandomPolynomial r = random_polynomial(random, degree);
            const std::vector<double>& roots = r.real_roots;
            for (std::size_t k = 0; k < roots.size(); ++k) {
                // A bracket around root k that reaches halfway to each neighbour.
                const double lo = k == 0 ? roots[k] - 0.3 : 0.5 * (roots[k - 1] + roots[k]);
                const double hi = k + 1 == roots.size() ? roots[k] + 0.3 : 0.5 * (roots[k] + roots[k + 1]);
                const double at_lo = r.polynomial.evaluate(lo), at_hi = r.polynomial.evaluate(hi);
                if (at_lo == 0 || at_hi == 0 || (at_lo < 0) == (at_hi < 0)) continue;
                RootFinderWork work;
                const RootTolerance tolerance;
                const double root = refine_bracketed_root(r.polynomial, lo, hi, at_lo, at_hi, tolerance, &work);
                ++brackets;
                ASSERT_GE(root, lo);
                ASSERT_LE(root, hi);
                // The sign change of p (its coefficients taken as exact, the oracle) lies within the tolerance and
                // the rounding of p's evaluation over its slope there of the root found.
                const std::vector<double> exact = oracle_roots(r.polynomial, lo, hi);
                ASSERT_EQ(exact.size(), 1u) << "degree " << degree << " trial " << trial;
                double magnitude = 0;  // Σ |cᵢ|·|t|ⁱ at the root
                for (int i = r.polynomial.degree(); i >= 0; --i)
                    magnitude = magnitude * std::abs(exact[0]) + std::abs(r.polynomial[i]);
                const double slope = std::abs(r.polynomial.evaluate_with_derivative(exact[0]).derivative);
                const double rounding = 64 * std::numeric_limits<double>::epsilon() * magnitude / slope;
                EXPECT_NEAR(root, exact[0], tolerance.width_at(root) + rounding)
                    << "degree " << degree << " trial " << trial;
                EXPECT_LT(work.iterations, 200u);
            }
        }
    }
    EXPECT_GT(brackets, 3000);
}

// Regression: at a bracket's end, a Newton step smaller than half an ulp of t left t where it was; the step counted
// as leaving the bracket, and bisection then halved a bracket of 3·10⁻¹¹ some 8 times (12 steps here, not 4).
TEST(BracketedRoot, AStepThatRoundsToNothingEndsTheSearch) {
    const Polynomial p{-0.3, 1.2, -0.5, 0.7, -0.2, 0.1, 0.05};
    RootFinderWork work;
    const double root = refine_bracketed_root(p, 0, 1, p.evaluate(0), p.evaluate(1), {}, &work);
    EXPECT_NEAR(root, 0.26960008776025923, 1e-15);
    EXPECT_LE(work.iterations, 5u);
}

// A first guess inside the bracket is where the search starts (at the root itself, one step confirms it); one outside
// the bracket, or none, starts at the secant's zero, step for step.
TEST(BracketedRoot, StartsAtAFirstGuessInsideTheBracket) {
    const Polynomial p{-0.3, 1.2, -0.5, 0.7, -0.2, 0.1, 0.05};
    const double at0 = p.evaluate(0), at1 = p.evaluate(1);
    RootFinderWork from_secant, from_root, from_outside;
    const double root = refine_bracketed_root(p, 0, 1, at0, at1, {}, &from_secant);
    EXPECT_EQ(refine_bracketed_root(p, 0, 1, at0, at1, {}, &from_root, root), root);
    EXPECT_LE(from_root.iterations, 2u);
    EXPECT_LT(from_root.iterations, from_secant.iterations);
    EXPECT_EQ(refine_bracketed_root(p, 0, 1, at0, at1, {}, &from_outside, 1.5), root);
    EXPECT_EQ(from_outside.iterations, from_secant.iterations);
}

}  // namespace
}  // namespace isotrace
