// Bounds of a difference of convex functions from values and slopes at the ends: they contain every value and slope
// sampled in between, close in quadratically as the stretch shrinks, are exact for linear parts, and lose only the
// tangent, not the bound, where an end's slope is not finite.
#include "geometry/field/difference_of_convex.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace isotrace {
namespace {

// c(t) = exp(t), s(t) = 2 cosh(t − 0.3): both convex, φ = c − s changes sign once.
DifferenceOfConvexSample sample(double t) {
    return {{std::exp(t), std::exp(t)}, {2 * std::cosh(t - 0.3), 2 * std::sinh(t - 0.3)}};
}
double phi(double t) { return std::exp(t) - 2 * std::cosh(t - 0.3); }
double phi_slope(double t) { return std::exp(t) - 2 * std::sinh(t - 0.3); }

TEST(DifferenceOfConvex, BoundsHoldEveryValueAndSlopeInBetween) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> where(-3, 3), width(1e-4, 2), fraction(0, 1);
    for (int i = 0; i < 2000; ++i) {
        const double a = where(random), b = a + width(random);
        const Interval range = difference_of_convex_range(a, sample(a), b, sample(b));
        const Interval slope = difference_of_convex_slope(sample(a), sample(b));
        for (int k = 0; k <= 20; ++k) {
            const double t = a + (b - a) * k / 20;
            const double slack = 1e-13 * (1 + std::abs(phi(t)));
            EXPECT_GE(phi(t), range.lo - slack) << a << " " << b;
            EXPECT_LE(phi(t), range.hi + slack) << a << " " << b;
            EXPECT_GE(phi_slope(t), slope.lo - slack);
            EXPECT_LE(phi_slope(t), slope.hi + slack);
        }
    }
}

TEST(DifferenceOfConvex, BoundsCloseInQuadratically) {
    // φ = t² − 2t² = −t² on [−h, 1.5h], its maximum 0 inside: halving h quarters the bounds' excess over its range.
    const auto at = [](double t) { return DifferenceOfConvexSample{{t * t, 2 * t}, {2 * t * t, 4 * t}}; };
    double previous = 0;
    for (int halvings = 0; halvings < 8; ++halvings) {
        const double h = std::ldexp(0.5, -halvings), a = -h, b = 1.5 * h;
        const Interval range = difference_of_convex_range(a, at(a), b, at(b));
        const double excess = range.hi - range.lo - b * b;  // φ's own range is [−b², 0]
        EXPECT_GT(excess, 0);
        if (halvings > 0) { EXPECT_NEAR(excess / previous, 0.25, 1e-9) << halvings; }
        previous = excess;
    }
}

TEST(DifferenceOfConvex, LinearPartsAreExact) {
    const DifferenceOfConvexSample at_a{{1, 2}, {0.5, -1}}, at_b{{5, 2}, {-1.5, -1}};  // c = 1 + 2t, s = 0.5 − t on [0, 2]
    const Interval range = difference_of_convex_range(0, at_a, 2, at_b);
    EXPECT_DOUBLE_EQ(range.lo, 0.5);
    EXPECT_DOUBLE_EQ(range.hi, 6.5);
    const Interval slope = difference_of_convex_slope(at_a, at_b);
    EXPECT_DOUBLE_EQ(slope.lo, 3);
    EXPECT_DOUBLE_EQ(slope.hi, 3);
}

TEST(DifferenceOfConvex, AnEndWithoutTangentKeepsTheBoundValid) {
    // √ at 0 has an unbounded slope: c = −√t is convex; without the tangent at 0 the bound still holds.
    const auto at = [](double t, bool cusp) {
        const double slope = cusp ? NAN : -0.5 / std::sqrt(t);
        return DifferenceOfConvexSample{{-std::sqrt(t), slope}, {0, 0}};
    };
    const Interval range = difference_of_convex_range(0, at(0, true), 1, at(1, false));
    for (int k = 0; k <= 100; ++k) {
        const double t = k / 100.0;
        EXPECT_GE(-std::sqrt(t), range.lo - 1e-15);
        EXPECT_LE(-std::sqrt(t), range.hi + 1e-15);
    }
    EXPECT_TRUE(std::isinf(difference_of_convex_slope(at(0, true), at(1, false)).lo));
    const Interval neither = difference_of_convex_range(0, at(0, true), 1, {{-1, NAN}, {0, 0}});
    EXPECT_TRUE(std::isinf(neither.lo));  // no tangent at all: nothing below
}

}  // namespace
}  // namespace isotrace
