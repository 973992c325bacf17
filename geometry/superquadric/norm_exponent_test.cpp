// The powers and roots of the gauge's p-norms against long double pow: within four ulps for the roots of every whole
// exponent up to 64 and of sampled fractional ones (a polynomial, its terms rounded once each), within six for the
// fractional powers up to p = 16 (a polynomial times a power of two's power) over every octave they take, and within
// three for the norms that fractional exponents up to p = 8 take from their own polynomials.
#include "geometry/superquadric/norm_exponent.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace isotrace {
namespace {

// The error of `computed` against `exact` in ulps of `exact`.
double ulps(double computed, long double exact) {
    const long double ulp = std::ldexp(1.0L, std::ilogb(double(exact)) - 52);
    return double(std::abs(computed - exact) / ulp);
}

// s over [1, 2]: a fine even grid with its ends, and the doubles just inside them.
std::vector<double> roots_arguments() {
    std::vector<double> s;
    for (int i = 0; i <= 20000; ++i) s.push_back(1 + i / 20000.0);
    s.push_back(std::nextafter(1.0, 2.0));
    s.push_back(std::nextafter(2.0, 1.0));
    return s;
}

TEST(SuperquadricNormExponent, RootsOfWholeExponentsAreWithinFourUlps) {
    const std::vector<double> arguments = roots_arguments();
    int tested = 0;
    for (int p = 1; p <= 64; ++p) {
        const NormExponent e = NormExponent::of_epsilon(2.0 / p);
        if (2 / (2.0 / p) != p) continue;  // ε = 2/p rounds to an ε whose 2/ε is not whole (49 is one)
        ASSERT_EQ(e.whole, p);
        ++tested;
        double worst = 0;
        for (double s : arguments) worst = std::max(worst, ulps(e.root(s), std::pow((long double)s, 1.0L / p)));
        EXPECT_LE(worst, 4.0) << "p = " << p;
    }
    EXPECT_GE(tested, 60);
}

TEST(SuperquadricNormExponent, RootsOfFractionalExponentsAreWithinFourUlps) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> epsilon(0.02, 4);
    const std::vector<double> arguments = roots_arguments();
    for (int i = 0; i < 50; ++i) {
        const NormExponent e = NormExponent::of_epsilon(epsilon(random));
        ASSERT_EQ(e.whole, 0);
        double worst = 0;
        for (std::size_t k = 0; k < arguments.size(); k += 7)
            worst = std::max(worst, ulps(e.root(arguments[k]), std::pow((long double)arguments[k], 1.0L / e.p)));
        EXPECT_LE(worst, 4.0) << "p = " << e.p;
    }
}

// Powers of shares by repeated squaring: a squaring doubles the relative error and adds a rounding, so r^p is within
// p − 1 roundings (which the root of 1 + r^p divides by p again); roots of any argument (the edge of a
// p-ball, 1 − w^p ∈ [0, 1]) in closed form or by pow of the rounded 1/p.
// On coordinate planes a power is of 0 and the p-ball's edge a root of 1: pow's exact answers, which fractional
// exponents take without the call; a share of 1 (the p-ball's pole) has the power 1 exactly, and shares below the
// table's 64 octaves take pow. (The roots of 1 + r^p are the polynomial's, tested above.)
TEST(SuperquadricNormExponent, PowersOfZeroAndOneAndEdgeRootsOfOneAreExact) {
    for (const double epsilon : {0.3, 0.7, 2.5, 3.5}) {
        const NormExponent e = NormExponent::of_epsilon(epsilon);
        ASSERT_TRUE(e.tabulated) << epsilon;
        EXPECT_EQ(e.unit_power(0), std::pow(0.0, e.p)) << epsilon;
        EXPECT_EQ(e.unit_power(1), 1) << epsilon;
        EXPECT_EQ(e.any_root(1), std::pow(1.0, e.inverse)) << epsilon;
        EXPECT_EQ(e.unit_power(0x1p-64), std::pow(0x1p-64, e.p)) << epsilon;
    }
}

TEST(SuperquadricNormExponent, FractionalPowersAreWithinSixUlpsOverEveryOctave) {
    std::mt19937 random(9);
    std::uniform_real_distribution<double> epsilon(0.02, 4), octaves(0, 70);
    int tabulated = 0;
    for (int i = 0; i < 60; ++i) {
        const NormExponent e = NormExponent::of_epsilon(epsilon(random));
        ASSERT_EQ(e.whole, 0);
        tabulated += e.tabulated;
        EXPECT_EQ(e.tabulated, e.p <= NormExponent::kMostTabulated) << e.p;
        double worst = 0;
        for (int k = 0; k < 4000; ++k) {
            // Shares just below each power of two, and spread over the octaves.
            const double r = k < 140 ? std::nextafter(std::exp2(-0.5 * k), 0.0) : std::exp2(-octaves(random));
            const long double power = std::pow((long double)r, (long double)e.p);
            if (power > 1e-300L) worst = std::max(worst, ulps(e.unit_power(r), power));
        }
        EXPECT_LE(worst, e.tabulated ? 6.0 : 1.0) << "p = " << e.p;
    }
    EXPECT_GE(tabulated, 20);
}

// The norm ‖(1, r)‖_p of fractional exponents up to p = 8 from its own polynomials, over the eight octaves they
// cover, against long double; r outside them (and other exponents) takes the root of 1 + r^p.
TEST(SuperquadricNormExponent, TabulatedNormsAreWithinThreeUlps) {
    std::mt19937 random(10);
    std::uniform_real_distribution<double> epsilon(0.25, 4), octaves(0, 8);
    int tabulated = 0;
    for (int i = 0; i < 40; ++i) {
        const NormExponent e = NormExponent::of_epsilon(epsilon(random));
        EXPECT_EQ(e.norm_tabulated, e.whole == 0 && e.p <= NormExponent::kMostNormTabulated) << e.p;
        if (!e.norm_tabulated) continue;
        ++tabulated;
        double worst = 0;
        for (int k = 0; k < 3000; ++k) {
            // Shares just below and at each power of two, and spread over the octaves.
            const double r = k < 18 ? std::exp2(-0.5 * (k + 1)) : k < 36 ? std::nextafter(std::exp2(-0.5 * (k - 17)), 0.0)
                                                                       : std::exp2(-octaves(random));
            ASSERT_EQ(e.has_tabulated_norm(r), r >= 0x1p-8 && r < 1) << r;  // 2^−8: the eight octaves
            if (!e.has_tabulated_norm(r)) continue;
            const long double exact = std::pow(1 + std::pow((long double)r, (long double)e.p), 1 / (long double)e.p);
            worst = std::max(worst, ulps(e.tabulated_norm(r), exact));
        }
        EXPECT_LE(worst, 3.0) << "p = " << e.p;
    }
    EXPECT_GE(tabulated, 20);
    // Whole exponents and those above p = 8 have none.
    for (const double epsilon : {1.0, 2.0, 0.5, 0.2, 0.15}) EXPECT_FALSE(NormExponent::of_epsilon(epsilon).norm_tabulated);
}

TEST(SuperquadricNormExponent, PowersAndRootsOfAnyArgumentAreWithinAFewUlps) {
    std::mt19937 random(8);
    std::uniform_real_distribution<double> unit(0, 1);
    for (const double epsilon : {2.0, 1.0, 0.5, 2.0 / 3, 0.3, 0.1, 0.02, 2.5, 4.0}) {
        const NormExponent e = NormExponent::of_epsilon(epsilon);
        for (int i = 0; i < 2000; ++i) {
            const double r = unit(random);
            const long double power = std::pow((long double)r, (long double)e.p);
            const double allowed = e.whole > 0 ? e.p - 1 : e.tabulated ? 6.0 : 1.0;
            if (power > 1e-300L) { EXPECT_LE(ulps(e.unit_power(r), power), allowed) << e.p << " " << r; }
            EXPECT_LE(ulps(e.any_root(r), std::pow((long double)r, (long double)e.inverse)), 1.0) << e.p << " " << r;
        }
        EXPECT_EQ(e.unit_power(0), 0);
        EXPECT_EQ(e.unit_power(1), 1);
        EXPECT_EQ(e.any_root(0), 0);
    }
}

}  // namespace
}  // namespace isotrace
