// Polynomial value type: construction, Horner evaluation, derivatives, arithmetic, reparametrisation, trimming
// of negligible leading terms, normalisation and Euclidean remainders.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "geometry/polynomial/polynomial.h"
#include "geometry/polynomial/polynomial_test_support.h"

namespace isotrace {
namespace {

TEST(PolynomialTest, ConstructionDropsExactlyZeroLeadingCoefficients) {
    EXPECT_EQ(Polynomial({1, 2, 0, 0}).degree(), 1);
    EXPECT_TRUE(Polynomial().is_zero());
    EXPECT_TRUE(Polynomial({0, 0}).is_zero());
    EXPECT_EQ(Polynomial({0, 0, 3}).degree(), 2);
    EXPECT_EQ(Polynomial({0, 0, 3})[2], 3);
}

TEST(PolynomialTest, DegreeAboveTheMaximumThrows) {
    const std::vector<double> eleven_roots(kMaxPolynomialDegree + 1, 0.5);
    EXPECT_THROW(polynomial_from_roots(eleven_roots), std::length_error);
    const std::vector<double> ten_roots(kMaxPolynomialDegree, 0.5);
    EXPECT_EQ(polynomial_from_roots(ten_roots).degree(), kMaxPolynomialDegree);
    const Polynomial six = polynomial_from_roots(std::vector<double>(6, 1.0));
    EXPECT_THROW(six * six, std::length_error);
}

TEST(PolynomialTest, EvaluatesWithHornerAndItsDerivative) {
    const Polynomial p{1, -3, 0, 2};  // 1 − 3t + 2t³
    for (double t : {-2.0, -0.5, 0.0, 0.3, 1.7}) {
        EXPECT_DOUBLE_EQ(p.evaluate(t), 1 - 3 * t + 2 * t * t * t);
        const ValueAndDerivative both = p.evaluate_with_derivative(t);
        EXPECT_DOUBLE_EQ(both.value, p.evaluate(t));
        EXPECT_DOUBLE_EQ(both.derivative, -3 + 6 * t * t);
        EXPECT_DOUBLE_EQ(p.derivative().evaluate(t), both.derivative);
    }
    EXPECT_TRUE(Polynomial{5}.derivative().is_zero());
}

TEST(PolynomialTest, FromRootsVanishesAtItsRoots) {
    const std::vector<double> roots{-1, 0.25, 2};
    const Polynomial p = polynomial_from_roots(roots, 3);
    EXPECT_EQ(p.degree(), 3);
    EXPECT_EQ(p[3], 3);
    for (double root : roots) EXPECT_EQ(p.evaluate(root), 0);
    EXPECT_DOUBLE_EQ(p.evaluate(1), 3 * 2 * 0.75 * -1);
}

TEST(PolynomialTest, ArithmeticMatchesPointwiseArithmetic) {
    const Polynomial p{1, 2, 3}, q{-1, 0, 0, 4};
    for (double t : {-1.5, 0.0, 0.7, 3.0}) {
        EXPECT_DOUBLE_EQ((p + q).evaluate(t), p.evaluate(t) + q.evaluate(t));
        EXPECT_DOUBLE_EQ((p - q).evaluate(t), p.evaluate(t) - q.evaluate(t));
        EXPECT_DOUBLE_EQ((p * q).evaluate(t), p.evaluate(t) * q.evaluate(t));
        EXPECT_DOUBLE_EQ((2.5 * p).evaluate(t), 2.5 * p.evaluate(t));
    }
    EXPECT_EQ((p * q).degree(), 5);
    EXPECT_EQ((q - Polynomial{0, 0, 0, 4}).degree(), 0);  // cancellation lowers the degree
    EXPECT_TRUE((p - p).is_zero());
}

TEST(PolynomialTest, ComposeLinearReparametrisesOntoTheUnitInterval) {
    std::mt19937_64 random(7);
    const Polynomial p = random_polynomial(random, 7).polynomial;
    const double a = -0.3, b = 1.9;
    const Polynomial q = p.compose_linear(a, b - a);
    EXPECT_EQ(q.degree(), 7);
    for (double u : {0.0, 0.1, 0.5, 0.77, 1.0})
        EXPECT_NEAR(q.evaluate(u), p.evaluate(a + (b - a) * u), 1e-12);
}

TEST(PolynomialTest, NegligibleLeadingTermsAreDroppedRelativeToTheInterval) {
    const Polynomial p = Polynomial{0, 0, 0, 0, 0, 1e-20} + polynomial_from_roots(std::vector<double>{0.3, 0.6});
    EXPECT_EQ(p.degree(), 5);
    EXPECT_EQ(p.without_negligible_leading_terms(0, 1).degree(), 2);
    // Far from the origin the same term dominates and must stay.
    EXPECT_EQ(p.without_negligible_leading_terms(0, 1e6).degree(), 5);
    EXPECT_EQ(Polynomial({1e-300}).without_negligible_leading_terms(0, 1).degree(), 0);
}

TEST(PolynomialTest, NormalisedScalesByAPowerOfTwo) {
    const Polynomial p{3e-30, -5e-29, 1e-31};
    const Polynomial n = p.normalised();
    EXPECT_GE(std::abs(n[1]), 1.0);
    EXPECT_LT(std::abs(n[1]), 2.0);
    const double scale = n[1] / p[1];
    EXPECT_EQ(std::exp2(std::round(std::log2(scale))), scale);
    for (int i = 0; i <= 2; ++i) EXPECT_EQ(n[i], p[i] * scale);
}

TEST(PolynomialTest, RemainderOfEuclideanDivision) {
    // (t³ − 2t + 5) = (t² + 1)(t) + (−3t + 5)
    const Polynomial rest = Polynomial{5, -2, 0, 1}.remainder(Polynomial{1, 0, 1});
    EXPECT_EQ(rest.degree(), 1);
    EXPECT_DOUBLE_EQ(rest[0], 5);
    EXPECT_DOUBLE_EQ(rest[1], -3);
    EXPECT_TRUE(polynomial_from_roots(std::vector<double>{1, 2, 3})
                    .remainder(polynomial_from_roots(std::vector<double>{1, 2}))
                    .is_zero());
    EXPECT_TRUE((Polynomial{1, 2}.remainder(Polynomial{4}).is_zero()));
    // (t + 1)² + 2⁻⁵² divided by t + 1 leaves 2⁻⁵², which is cancellation noise relative to the 1s that cancelled.
    const Polynomial almost_square{1 + 0x1p-52, 2, 1};
    EXPECT_EQ(almost_square.remainder(Polynomial{1, 1})[0], 0x1p-52);
    EXPECT_TRUE(almost_square.remainder(Polynomial{1, 1}, 1e-13).is_zero());
    // A small remainder where nothing cancelled is a real value and stays.
    EXPECT_FALSE((Polynomial{1e-17, 0, 1}.remainder(Polynomial{0, 1}, 1e-13).is_zero()));
}

}  // namespace
}  // namespace isotrace
