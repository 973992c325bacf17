// The monotone-interval finder's own contract: first_root is the smallest of all_roots, and tangent roots are
// reported once with their flag. Accuracy against the oracle is in root_finders_test.cpp.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "geometry/polynomial/monotone_root_finder.h"
#include "geometry/polynomial/polynomial_test_support.h"
#include "tests/support/sturm_sequence.h"

namespace isotrace {
namespace {

TEST(PolynomialMonotoneRootFinder, FirstRootIsTheSmallestRoot) {
    std::mt19937_64 random(5);
    for (int trial = 0; trial < 500; ++trial) {
        const Polynomial p = random_polynomial(random, 2 + trial % 9).polynomial;
        const PolynomialRoots all = all_roots(p, 0, 1);
        const std::optional<PolynomialRoot> first = first_root(p, 0, 1);
        ASSERT_EQ(first.has_value(), !all.empty());
        if (first) {
            EXPECT_EQ(first->t, all[0].t);
        }
    }
    EXPECT_FALSE(first_root(Polynomial{1, 0, 1}, -1, 1));
    EXPECT_EQ(first_root(polynomial_from_roots(std::vector<double>{0, 0.5}), 0, 1)->t, 0);
}

TEST(PolynomialMonotoneRootFinder, TangentRootsAreReportedOnceWithTheirFlag) {
    for (double double_root : {0.25, 0.3, 0.8123456789}) {
        const Polynomial p = polynomial_from_roots(std::vector<double>{double_root, double_root, 0.6, 1.4, -0.1});
        const PolynomialRoots roots = all_roots(p, 0, 1);
        ASSERT_EQ(roots.size(), 2) << double_root;
        const PolynomialRoot& tangent = double_root < 0.6 ? roots[0] : roots[1];
        const PolynomialRoot& crossing = double_root < 0.6 ? roots[1] : roots[0];
        EXPECT_NEAR(tangent.t, double_root, 1e-6);
        EXPECT_TRUE(tangent.tangent);
        EXPECT_NEAR(crossing.t, 0.6, 1e-12);
        EXPECT_FALSE(crossing.tangent);
    }
    // A grazing contact at scale 1e30 is still within rounding of zero relative to the coefficients.
    const PolynomialRoots grazing = all_roots(polynomial_from_roots(std::vector<double>{0.5, 0.5}, 1e30), 0, 1);
    ASSERT_EQ(grazing.size(), 1);
    EXPECT_TRUE(grazing[0].tangent);
    // A quadruple root is one tangent root too.
    const PolynomialRoots quadruple = all_roots(polynomial_from_roots(std::vector<double>(4, 0.375)), 0, 1);
    ASSERT_EQ(quadruple.size(), 1);
    EXPECT_NEAR(quadruple[0].t, 0.375, 1e-3);
}

TEST(PolynomialMonotoneRootFinder, AgreesWithSturmOnRandomHighDegreePolynomials) {
    std::mt19937_64 random(8);
    for (int trial = 0; trial < 300; ++trial) {
        const Polynomial p = random_polynomial(random, kMaxPolynomialDegree, -0.5, 1.5, 1e-4).polynomial;
        expect_same_roots(p, root_values(all_roots(p, 0, 1)), root_values(sturm_roots(p, 0, 1)), 1e-9);
    }
}

}  // namespace
}  // namespace isotrace
