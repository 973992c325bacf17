#include "tests/support/chi_square.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace isotrace::test_support {
namespace {

// Closed forms to compare against: for integer a, Q(a, x) is a Poisson tail; for a = 1/2, erfc(sqrt(x)).
double poisson_upper_gamma(int a, double x) {
    double term = std::exp(-x), sum = 0;
    for (int k = 0; k < a; ++k) {
        sum += term;
        term *= x / (k + 1);
    }
    return sum;
}

TEST(IncompleteGamma, MatchesPoissonTailForIntegerShape) {
    // x values on both sides of a + 1 exercise the series and the continued fraction.
    for (int a : {1, 2, 5, 20, 60}) {
        for (double x : {0.05, 0.5, 1.0, 3.0, 7.5, 19.0, 21.5, 40.0, 80.0}) {
            const double q = poisson_upper_gamma(a, x);
            EXPECT_NEAR(regularized_gamma_q(a, x), q, 1e-12 + 1e-10 * q) << "a=" << a << " x=" << x;
            EXPECT_NEAR(regularized_gamma_p(a, x), 1.0 - q, 1e-12) << "a=" << a << " x=" << x;
        }
    }
}

TEST(IncompleteGamma, MatchesErfcForHalfShape) {
    for (double x : {1e-4, 0.1, 1.0, 2.0, 10.0, 30.0}) {
        const double q = std::erfc(std::sqrt(x));
        EXPECT_NEAR(regularized_gamma_q(0.5, x), q, 1e-13 + 1e-10 * q) << "x=" << x;
    }
}

TEST(IncompleteGamma, EdgesAndInvalidArguments) {
    EXPECT_EQ(regularized_gamma_p(3.0, 0.0), 0.0);
    EXPECT_EQ(regularized_gamma_q(3.0, 0.0), 1.0);
    EXPECT_THROW(regularized_gamma_q(0.0, 1.0), std::invalid_argument);
    EXPECT_THROW(regularized_gamma_p(1.0, -1.0), std::invalid_argument);
    EXPECT_THROW(regularized_gamma_p(1.0, NAN), std::invalid_argument);
}

TEST(ChiSquarePValue, KnownCriticalValues) {
    EXPECT_NEAR(chi_square_p_value(3.84, 1), 0.05, 2e-4);
    EXPECT_NEAR(chi_square_p_value(3.841458820694124, 1), 0.05, 1e-12);
    EXPECT_NEAR(chi_square_p_value(5.991464547107979, 2), 0.05, 1e-12);
    EXPECT_NEAR(chi_square_p_value(18.307038053275146, 10), 0.05, 1e-12);
    EXPECT_NEAR(chi_square_p_value(6.634896601021214, 1), 0.01, 1e-12);
    EXPECT_NEAR(chi_square_p_value(124.3421134, 100), 0.05, 1e-7);
    EXPECT_NEAR(chi_square_p_value(4.0, 2), std::exp(-2.0), 1e-14);  // 2 dof is an exponential tail
}

TEST(ChiSquareTest, PerfectFitHasStatisticZero) {
    const std::vector<double> counts = {10, 20, 30, 40};
    const ChiSquareResult result = chi_square_test(counts, counts);
    EXPECT_EQ(result.statistic, 0.0);
    EXPECT_EQ(result.dof, 3);
    EXPECT_NEAR(result.p_value, 1.0, 1e-12);
}

TEST(ChiSquareTest, PoolsSparseBins) {
    // The five bins expecting 1 sample are pooled into one bin expecting 5 (observed 8).
    const std::vector<double> observed = {90, 102, 2, 0, 3, 1, 2};
    const std::vector<double> expected = {100, 95, 1, 1, 1, 1, 1};
    const ChiSquareResult result = chi_square_test(observed, expected);
    EXPECT_EQ(result.dof, 2);
    EXPECT_NEAR(result.statistic, 100.0 / 100 + 49.0 / 95 + 9.0 / 5, 1e-12);
}

TEST(ChiSquareTest, UnderfullPoolAbsorbsTheNextBin) {
    // The pool expecting 2 absorbs the next-smallest bin, however large, rather than standing alone.
    const std::vector<double> observed = {50, 60, 3};
    const std::vector<double> expected = {55, 56, 2};
    const ChiSquareResult result = chi_square_test(observed, expected);
    EXPECT_EQ(result.dof, 1);
    EXPECT_NEAR(result.statistic, 16.0 / 57 + 16.0 / 56, 1e-12);
}

TEST(ChiSquareTest, LeftoverPoolJoinsFirstBin) {
    // Bins 0+1 and 2+3 become pools expecting 6; bin 4 is left over and joins the first of them.
    const std::vector<double> observed = {5, 2, 4, 3, 1};
    const std::vector<double> expected = {3, 3, 3, 3, 3};
    const ChiSquareResult result = chi_square_test(observed, expected);
    EXPECT_EQ(result.dof, 1);
    EXPECT_NEAR(result.statistic, 1.0 / 9 + 1.0 / 6, 1e-12);
}

TEST(ChiSquareTest, SampleWhereNoneExpectedFails) {
    const std::vector<double> observed = {50, 49, 1};
    const std::vector<double> expected = {50, 50, 0};
    EXPECT_EQ(chi_square_test(observed, expected).p_value, 0.0);
}

TEST(ChiSquareTest, GrossMisfitHasTinyPValue) {
    const std::vector<double> observed = {700, 300};
    const std::vector<double> expected = {500, 500};
    EXPECT_LT(chi_square_test(observed, expected).p_value, 1e-20);
}

TEST(ChiSquareTest, RejectsUnusableInput) {
    const std::vector<double> two = {1, 2}, three = {1, 2, 3};
    EXPECT_THROW(chi_square_test(two, three), std::invalid_argument);
    const std::vector<double> sparse = {1, 1};
    EXPECT_THROW(chi_square_test(sparse, sparse), std::invalid_argument);  // pools into a single bin
}

TEST(SidakSignificance, KeepsFamilyWiseRate) {
    EXPECT_NEAR(sidak_significance(0.01, 1), 0.01, 1e-15);
    const double per_test = sidak_significance(0.01, 10);
    EXPECT_NEAR(1.0 - std::pow(1.0 - per_test, 10), 0.01, 1e-14);
    EXPECT_LT(per_test, 0.01 / 10 * 1.01);
}

// A deterministic, well-mixed point sequence in [0,1)^2 (golden-ratio and hash based, independent of the
// renderer's samplers so this helper is tested on its own).
Point2 test_point(std::size_t i) {
    auto mix = [](unsigned long long z) {
        z = (z ^ (z >> 33)) * 0xff51afd7ed558ccdull;
        z = (z ^ (z >> 33)) * 0xc4ceb9fe1a85ec53ull;
        return static_cast<double>((z ^ (z >> 33)) >> 11) * 0x1p-53;
    };
    return {mix(2 * i + 1), mix(2 * i + 2)};
}

TEST(ChiSquareTest2D, UniformPointsFitUniformDensity) {
    const Grid2D grid{0, 1, 0, 1, 16, 16};
    const ChiSquareResult result = chi_square_test_2d(grid, 100000, test_point, [](double, double) { return 1.0; });
    EXPECT_EQ(result.dof, 255);  // 256 cells; the "outside" bin expects nothing and is dropped
    EXPECT_GT(result.p_value, 0.01);
}

TEST(ChiSquareTest2D, DetectsWrongDensity) {
    const Grid2D grid{0, 1, 0, 1, 16, 16};
    const auto skewed = [](double x, double) { return 0.9 + 0.2 * x; };  // integrates to 1
    EXPECT_LT(chi_square_test_2d(grid, 100000, test_point, skewed).p_value, 1e-6);
}

TEST(ChiSquareTest2D, PointsOutsideTheDomainFail) {
    const Grid2D grid{0, 1, 0, 1, 8, 8};
    const auto mostly_inside = [](std::size_t i) { return i == 7 ? Point2{1.5, 0.5} : test_point(i); };
    EXPECT_EQ(chi_square_test_2d(grid, 10000, mostly_inside, [](double, double) { return 1.0; }).p_value, 0.0);
}

TEST(ExpectedCounts2D, IntegratesDiscontinuousDensity) {
    // Indicator of the unit disk on [-1,1]^2, counted with 1e6 samples: the total is pi * 1e6.
    const Grid2D grid{-1, 1, -1, 1, 10, 10};
    const auto disk = [](double x, double y) { return x * x + y * y < 1 ? 1.0 : 0.0; };
    const std::vector<double> expected = expected_counts_2d(grid, 1000000, disk);
    double total = 0;
    for (double e : expected) total += e;
    EXPECT_NEAR(total, std::numbers::pi * 1e6, 2.0);
    EXPECT_NEAR(expected[4 * 10 + 4], 0.04 * 1e6, 1e-6);  // a cell wholly inside the disk
    EXPECT_EQ(expected[0], 0.0);                           // the corner cell lies wholly outside
}

}  // namespace
}  // namespace isotrace::test_support
