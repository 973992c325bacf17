// Both root finders (Sturm bisection and the monotone-interval finder) on the same cases, against known roots and
// the long-double brute-force oracle: separated, clustered and double roots, roots at the interval ends, extreme
// coefficient scales, negligible leading coefficients and random polynomials of degree 2..10.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "geometry/polynomial/monotone_root_finder.h"
#include "geometry/polynomial/polynomial_test_support.h"
#include "tests/support/sturm_sequence.h"

namespace isotrace {
namespace {

using RootFinder = PolynomialRoots (*)(const Polynomial&, double, double, const RootTolerance&);

struct NamedRootFinder {
    std::string name;
    RootFinder find;
};

// GoogleTest prints a parameter; without this it dumps the struct's bytes, uninitialised ones included (valgrind
// reported each such read).
void PrintTo(const NamedRootFinder& finder, std::ostream* out) { *out << finder.name; }

// Simple roots agree with the oracle to this relative accuracy.
constexpr double kSimpleRootTolerance = 1e-9;
// A double root moves by ~√ε under coefficient rounding, so it is only defined that well.
constexpr double kDoubleRootTolerance = 1e-6;

class RootFinderTest : public ::testing::TestWithParam<NamedRootFinder> {
protected:
    std::vector<double> roots(const Polynomial& p, double a, double b) const {
        return root_values(GetParam().find(p, a, b, RootTolerance{}));
    }
};

TEST_P(RootFinderTest, WellSeparatedRoots) {
    const std::vector<double> known{-0.4, 0.1, 0.35, 0.6, 0.95, 1.3};
    const Polynomial p = polynomial_from_roots(known, -2);
    expect_same_roots(p, roots(p, 0, 1), oracle_roots(p, 0, 1), kSimpleRootTolerance);
    expect_same_roots(p, roots(p, 0, 1), {0.1, 0.35, 0.6, 0.95}, kSimpleRootTolerance);
    expect_same_roots(p, roots(p, -1, 2), known, kSimpleRootTolerance);
    EXPECT_TRUE(roots(p, 0.2, 0.3).empty());
}

TEST_P(RootFinderTest, ClusteredRootsOneMillionthApart) {
    const Polynomial p = polynomial_from_roots(std::vector<double>{0.3, 0.3 + 1e-6, 0.7, 0.7 + 1e-6, -0.2}, 3);
    const std::vector<double> oracle = oracle_roots(p, 0, 1, 1 << 21);  // steps below the cluster spacing
    ASSERT_EQ(oracle.size(), 4u);
    expect_same_roots(p, roots(p, 0, 1), oracle, kSimpleRootTolerance);
}

TEST_P(RootFinderTest, DoubleRootsAreFoundNearTheirTrueLocation) {
    for (double double_root : {0.25, 0.3, 0.8123456789}) {
        const Polynomial p = polynomial_from_roots(std::vector<double>{double_root, double_root, 0.6, 1.4, -0.1});
        const std::vector<double> found = roots(p, 0, 1);
        // Rounding may turn a double root into two roots ~√ε apart; each must be near it, and 0.6 stays exact.
        ASSERT_GE(found.size(), 2u) << double_root;
        ASSERT_LE(found.size(), 3u) << double_root;
        for (double t : found) {
            if (std::abs(t - 0.6) < 0.1) EXPECT_NEAR(t, 0.6, kSimpleRootTolerance);
            else EXPECT_NEAR(t, double_root, kDoubleRootTolerance);
        }
    }
}

TEST_P(RootFinderTest, ExtremaAwayFromZeroAreNotRoots) {
    const Polynomial parabola = polynomial_from_roots(std::vector<double>{0.5, 0.5});
    EXPECT_TRUE(roots(parabola + Polynomial{1e-3}, 0, 1).empty());
    const Polynomial dipping = parabola - Polynomial{1e-6};
    expect_same_roots(dipping, roots(dipping, 0, 1), {0.499, 0.501}, kSimpleRootTolerance);
}

// The interval is closed: a root exactly at either end is reported, once.
TEST_P(RootFinderTest, RootsAtTheEndsAreIncluded) {
    const Polynomial p = polynomial_from_roots(std::vector<double>{0, 0.5, 1});
    expect_same_roots(p, roots(p, 0, 1), {0, 0.5, 1}, kSimpleRootTolerance);
    expect_same_roots(p, roots(p, 0, 0.5), {0, 0.5}, kSimpleRootTolerance);
    expect_same_roots(p, roots(p, 0.5, 1), {0.5, 1}, kSimpleRootTolerance);
    expect_same_roots(p, roots(p, 0.25, 0.75), {0.5}, kSimpleRootTolerance);
    // Ends that are not representable: p(0.1) rounds to ±tiny rather than 0, still a root.
    const Polynomial q = polynomial_from_roots(std::vector<double>{0.1, 0.7, 0.9});
    expect_same_roots(q, roots(q, 0.1, 0.7), {0.1, 0.7}, kSimpleRootTolerance);
    expect_same_roots(q, roots(q, 0.7, 0.9), {0.7, 0.9}, kSimpleRootTolerance);
}

TEST_P(RootFinderTest, HugeAndTinyCoefficientScales) {
    const std::vector<double> known{0.15, 0.4, 0.85, 1.7, -3};
    for (double scale : {1e30, 1e-30, -1e30, -1e-30}) {
        const Polynomial p = polynomial_from_roots(known, scale);
        expect_same_roots(p, roots(p, 0, 1), {0.15, 0.4, 0.85}, kSimpleRootTolerance);
        expect_same_roots(p, roots(p, -4, 4), {-3, 0.15, 0.4, 0.85, 1.7}, kSimpleRootTolerance);
    }
    // Large t: roots near 1e4 are found to relative accuracy.
    const Polynomial far = polynomial_from_roots(std::vector<double>{1e4, 1e4 + 1, 2e4});
    expect_same_roots(far, roots(far, 0, 3e4), {1e4, 1e4 + 1, 2e4}, kSimpleRootTolerance);
}

// A leading coefficient that cannot matter on [a, b] is a lower effective degree; its far-away root is outside.
TEST_P(RootFinderTest, NearlyZeroLeadingCoefficient) {
    const Polynomial quadratic = polynomial_from_roots(std::vector<double>{0.3, 0.6});
    for (double tiny : {1e-20, -1e-17, 1e-300}) {
        const Polynomial p = Polynomial{0, 0, 0, 0, 0, 0, tiny} + quadratic;
        EXPECT_EQ(p.degree(), 6);
        expect_same_roots(p, roots(p, 0, 1), {0.3, 0.6}, kSimpleRootTolerance);
    }
    // Small but significant on [0,1]: the roots really do move, and the oracle follows them.
    const Polynomial p = Polynomial{0, 0, 0, 0, 0, 0, 1e-9} + quadratic;
    expect_same_roots(p, roots(p, 0, 1), oracle_roots(p, 0, 1), kSimpleRootTolerance);
}

TEST_P(RootFinderTest, LowDegreesAndConstants) {
    EXPECT_TRUE(roots(Polynomial{}, 0, 1).empty());
    EXPECT_TRUE(roots(Polynomial{2}, 0, 1).empty());
    const Polynomial line{-0.25, 1}, parabola{1, 0, -4};
    expect_same_roots(line, roots(line, 0, 1), {0.25}, kSimpleRootTolerance);
    EXPECT_TRUE(roots(line, 0.5, 1).empty());
    expect_same_roots(parabola, roots(parabola, -1, 1), {-0.5, 0.5}, kSimpleRootTolerance);
}

// Random products with roots inside and outside [0,1] (and complex pairs), degree 2..10, against the oracle and
// against the construction.
TEST_P(RootFinderTest, RandomPolynomialsAgreeWithTheOracle) {
    std::mt19937_64 random(2022);
    for (int trial = 0; trial < 900; ++trial) {
        const int degree = 2 + trial % 9;
        const RandomPolynomial r = random_polynomial(random, degree);
        const std::vector<double> found = roots(r.polynomial, 0, 1);
        SCOPED_TRACE("trial " + std::to_string(trial));
        expect_same_roots(r.polynomial, found, oracle_roots(r.polynomial, 0, 1), kSimpleRootTolerance);
        expect_same_roots(r.polynomial, found, roots_inside(r.real_roots, 0, 1), 1e-7);
    }
}

// Random coefficients uniform in [−1,1]: no structure assumed, the oracle decides.
TEST_P(RootFinderTest, RandomCoefficientsAgreeWithTheOracle) {
    std::mt19937_64 random(4);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (int trial = 0; trial < 900; ++trial) {
        std::vector<double> coefficients(3 + trial % 9);
        for (double& c : coefficients) c = uniform(random);
        const Polynomial p{std::span<const double>(coefficients)};
        SCOPED_TRACE("trial " + std::to_string(trial));
        expect_same_roots(p, roots(p, -1, 1), oracle_roots(p, -1, 1, 8192), kSimpleRootTolerance);
    }
}

INSTANTIATE_TEST_SUITE_P(PolynomialRootFinders, RootFinderTest,
                         ::testing::Values(NamedRootFinder{"Sturm", &sturm_roots},
                                           NamedRootFinder{"Monotone",
                                                           [](const Polynomial& p, double a, double b,
                                                              const RootTolerance& tolerance) {
                                                               return all_roots(p, a, b, tolerance);
                                                           }}),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace isotrace
