// Interval operations hold every value of their function over the operands (random intervals, dense sampling),
// unbounded operands give no NaN ends, and the special places are handled: tan's poles, atan2's branch cut and
// origin, 1/b for b holding 0; the sine and cosine ranges of one angle from sincos are the two functions' own.
#include "renderer/math/interval.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <vector>

namespace isotrace {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

void expect_holds(const char* name, const std::function<Interval(Interval, Interval)>& bound,
                  const std::function<double(double, double)>& f, double spread) {
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int trial = 0; trial < 2000; ++trial) {
        const double a0 = spread * (2 * unit(random) - 1), b0 = spread * (2 * unit(random) - 1);
        const Interval a{a0, a0 + spread * unit(random) * (trial % 3 == 0 ? 0.01 : 1)};
        const Interval b{b0, b0 + spread * unit(random)};
        const Interval r = bound(a, b);
        for (int sample = 0; sample < 50; ++sample) {
            const double u = a.lo + a.width() * unit(random), v = b.lo + b.width() * unit(random);
            const double value = f(u, v);
            const double tolerance = 1e-14 * (1 + std::abs(value));
            ASSERT_TRUE(r.lo - tolerance <= value && value <= r.hi + tolerance)
                << name << "(" << u << ", " << v << ") = " << value << " outside [" << r.lo << ", " << r.hi << "]";
        }
    }
}

TEST(Interval, OperationsHoldEverySampledValue) {
    expect_holds("product", [](Interval a, Interval b) { return a * b; }, [](double u, double v) { return u * v; }, 3);
    expect_holds("negation", [](Interval a, Interval) { return -a; }, [](double u, double) { return -u; }, 3);
    expect_holds("min", [](Interval a, Interval b) { return min(a, b); }, [](double u, double v) { return std::min(u, v); }, 3);
    expect_holds("max", [](Interval a, Interval b) { return max(a, b); }, [](double u, double v) { return std::max(u, v); }, 3);
    expect_holds("hull", [](Interval a, Interval b) { return hull(a, b); }, [](double u, double) { return u; }, 3);
    expect_holds("square", [](Interval a, Interval) { return square(a); }, [](double u, double) { return u * u; }, 3);
    for (int n = 1; n <= 6; ++n)
        expect_holds("pow_int", [n](Interval a, Interval) { return pow_int(a, n); },
                     [n](double u, double) { return std::pow(u, n); }, 2);
    expect_holds("reciprocal", [](Interval, Interval b) { return reciprocal(b); }, [](double, double v) { return 1 / v; }, 3);
    expect_holds("exp", [](Interval a, Interval) { return exp(a); }, [](double u, double) { return std::exp(u); }, 5);
    expect_holds("atan", [](Interval a, Interval) { return atan(a); }, [](double u, double) { return std::atan(u); }, 5);
    expect_holds("sqrt", [](Interval a, Interval) { return sqrt_of_non_negative(a); },
                 [](double u, double) { return std::sqrt(std::max(u, 0.0)); }, 3);
    expect_holds("log", [](Interval a, Interval) { return log_above(a, 1e-3); },
                 [](double u, double) { return std::log(std::max(u, 1e-3)); }, 3);
    expect_holds("sign", [](Interval a, Interval) { return sign_range(a); }, [](double u, double) { return u < 0 ? -1.0 : 1.0; }, 3);
    expect_holds("tan", [](Interval a, Interval) { return tan_range(a); }, [](double u, double) { return std::tan(u); }, 6);
    expect_holds("atan2", [](Interval y, Interval x) { return atan2_range(y, x); },
                 [](double v, double u) { return std::atan2(v, u); }, 3);
}

TEST(Interval, UnboundedOperandsGiveNoNaNEnds) {
    const Interval all = Interval::unbounded(), zero = Interval::point(0);
    const Interval product = all * zero;
    EXPECT_EQ(product.lo, 0);
    EXPECT_EQ(product.hi, 0);
    const Interval half = Interval{0, inf} * Interval{0, 1};
    EXPECT_EQ(half.lo, 0);
    EXPECT_EQ(half.hi, inf);
    const Interval reciprocal_of_zero = reciprocal(Interval{-1, 1});
    EXPECT_EQ(reciprocal_of_zero.lo, -inf);
    EXPECT_EQ(reciprocal_of_zero.hi, inf);
}

// Intervals with infinite ends (the slabs outside a box, over which an isosurface's bound is proven) bound every
// finite value of their operands: ∞ − ∞, 0 · ∞ and the like give no NaN end and no end that excludes a value.
std::vector<double> finite_samples(Interval a) {
    std::vector<double> samples;
    for (double v : {0.0, 1e-300, 0.5, 1.0, 3.0, 7.25, 1e5, 3e15, 1e200, std::numeric_limits<double>::max()})
        for (double s : {v, -v})
            if (a.contains(s)) samples.push_back(s);
    if (std::isfinite(a.lo)) samples.push_back(a.lo);
    if (std::isfinite(a.hi)) samples.push_back(a.hi);
    return samples;
}

void expect_holds_over_unbounded(const char* name, const std::function<Interval(Interval, Interval)>& bound,
                                 const std::function<double(double, double)>& f) {
    const Interval operands[] = {{-inf, inf}, {2, inf}, {-inf, -2}, {0, inf}, {-inf, 0}, {-1, 3}, {0, 0}, {5, 5}};
    for (const Interval& a : operands)
        for (const Interval& b : operands) {
            const Interval r = bound(a, b);
            ASSERT_FALSE(std::isnan(r.lo) || std::isnan(r.hi)) << name << " has a NaN end";
            for (double u : finite_samples(a))
                for (double v : finite_samples(b)) {
                    const double value = f(u, v);
                    if (std::isnan(value)) continue;  // outside the function's domain (a rule's business)
                    const double tolerance = 1e-14 * std::abs(value);
                    ASSERT_TRUE(r.lo - tolerance <= value && value <= r.hi + tolerance)
                        << name << "(" << u << ", " << v << ") = " << value << " outside [" << r.lo << ", " << r.hi
                        << "] for [" << a.lo << ", " << a.hi << "], [" << b.lo << ", " << b.hi << "]";
                }
        }
}

TEST(Interval, InfiniteEndsBoundEveryFiniteValue) {
    expect_holds_over_unbounded("sum", [](Interval a, Interval b) { return a + b; }, [](double u, double v) { return u + v; });
    expect_holds_over_unbounded("difference", [](Interval a, Interval b) { return a - b; },
                                [](double u, double v) { return u - v; });
    expect_holds_over_unbounded("product", [](Interval a, Interval b) { return a * b; },
                                [](double u, double v) { return u * v; });
    for (double s : {0.0, -2.0, 0.5})
        expect_holds_over_unbounded("scaled", [s](Interval a, Interval) { return a * s; }, [s](double u, double) { return u * s; });
    expect_holds_over_unbounded("shifted", [](Interval a, Interval) { return a + 4.0; }, [](double u, double) { return u + 4; });
    expect_holds_over_unbounded("min", [](Interval a, Interval b) { return min(a, b); },
                                [](double u, double v) { return std::min(u, v); });
    expect_holds_over_unbounded("max", [](Interval a, Interval b) { return max(a, b); },
                                [](double u, double v) { return std::max(u, v); });
    expect_holds_over_unbounded("magnitude", [](Interval a, Interval) { return a.magnitude(); },
                                [](double u, double) { return std::abs(u); });
    expect_holds_over_unbounded("square", [](Interval a, Interval) { return square(a); }, [](double u, double) { return u * u; });
    for (int n = 1; n <= 4; ++n)
        expect_holds_over_unbounded("pow_int", [n](Interval a, Interval) { return pow_int(a, n); },
                                    [n](double u, double) { return std::pow(u, n); });
    expect_holds_over_unbounded("reciprocal", [](Interval, Interval b) { return reciprocal(b); },
                                [](double, double v) { return v == 0 ? 0 : 1 / v; });
    expect_holds_over_unbounded("exp", [](Interval a, Interval) { return exp(a); }, [](double u, double) { return std::exp(u); });
    expect_holds_over_unbounded("atan", [](Interval a, Interval) { return atan(a); }, [](double u, double) { return std::atan(u); });
    expect_holds_over_unbounded("sqrt", [](Interval a, Interval) { return sqrt_of_non_negative(a); },
                                [](double u, double) { return std::sqrt(std::max(u, 0.0)); });
    expect_holds_over_unbounded("log", [](Interval a, Interval) { return log_above(a, 1e-3); },
                                [](double u, double) { return std::log(std::max(u, 1e-3)); });
    expect_holds_over_unbounded("sign", [](Interval a, Interval) { return sign_range(a); },
                                [](double u, double) { return u < 0 ? -1.0 : 1.0; });
    expect_holds_over_unbounded("sin", [](Interval a, Interval) { return sin_range(a); }, [](double u, double) { return std::sin(u); });
    expect_holds_over_unbounded("cos", [](Interval a, Interval) { return cos_range(a); }, [](double u, double) { return std::cos(u); });
    expect_holds_over_unbounded("sin_cos", [](Interval a, Interval) { return sin_cos_range(a).cos; },
                                [](double u, double) { return std::cos(u); });
    expect_holds_over_unbounded("tan", [](Interval a, Interval) { return tan_range(a); }, [](double u, double) { return std::tan(u); });
    expect_holds_over_unbounded("atan2", [](Interval y, Interval x) { return atan2_range(y, x); },
                                [](double v, double u) { return std::atan2(v, u); });
}

// An angle so large that doubles are spaced wider than the period: the whole range, at once (counting the extrema
// by k·π once looped forever there, k + 1 rounding back to k).
TEST(Interval, HugeAnglesCoverAPeriod) {
    for (double angle : {1e17, -3e20, 1e300, std::numeric_limits<double>::max()}) {
        for (const Interval r : {sin_range(Interval::point(angle)), cos_range(Interval::point(angle))}) {
            EXPECT_EQ(r.lo, -1) << angle;
            EXPECT_EQ(r.hi, 1) << angle;
        }
        EXPECT_EQ(tan_range(Interval::point(angle)).hi, inf) << angle;
    }
}

TEST(Interval, TanIsUnboundedAcrossAPoleAndAtan2AcrossTheCut) {
    EXPECT_EQ(tan_range({1.5, 1.6}).hi, inf);
    EXPECT_TRUE(tan_range({-1.5, 1.5}).is_finite());
    EXPECT_EQ(tan_range({0, 4}).lo, -inf);
    EXPECT_EQ(atan2_range({-0.1, 0.1}, {-2, -1}).hi, std::numbers::pi);
    EXPECT_EQ(atan2_range({-0.1, 0.1}, {-2, -1}).lo, -std::numbers::pi);
    const Interval right = atan2_range({-0.1, 0.1}, {1, 2});
    EXPECT_NEAR(right.hi, std::atan2(0.1, 1), 1e-15);
    EXPECT_NEAR(right.lo, -std::atan2(0.1, 1), 1e-15);
}

// The sine and cosine ranges of one angle from sincos are exactly the two functions' own ranges.
TEST(Interval, SinCosRangeIsSinRangeAndCosRange) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> centre(-50, 50), log_width(-12, 1.2);
    for (int i = 0; i < 20000; ++i) {
        const double lo = centre(rng), hi = lo + std::pow(10.0, log_width(rng));
        const SinCosRange both = sin_cos_range({lo, hi});
        const Interval sin = sin_range({lo, hi}), cos = cos_range({lo, hi});
        ASSERT_EQ(both.sin.lo, sin.lo) << lo << " " << hi;
        ASSERT_EQ(both.sin.hi, sin.hi) << lo << " " << hi;
        ASSERT_EQ(both.cos.lo, cos.lo) << lo << " " << hi;
        ASSERT_EQ(both.cos.hi, cos.hi) << lo << " " << hi;
    }
}

}  // namespace
}  // namespace isotrace
