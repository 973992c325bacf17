// Sturm sequences: counting distinct roots in half-open intervals, multiple roots through the gcd, and
// normalisation keeping extreme scales finite.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/polynomial/polynomial_test_support.h"
#include "tests/support/sturm_sequence.h"

namespace isotrace {
namespace {

TEST(SturmSequence, CountsDistinctRootsInHalfOpenIntervals) {
    const SturmSequence sequence(polynomial_from_roots(std::vector<double>{-1, 0.25, 0.5, 2}));
    EXPECT_EQ(sequence.count_roots(0, 1), 2);
    EXPECT_EQ(sequence.count_roots(-10, 10), 4);
    EXPECT_EQ(sequence.count_roots(0.3, 0.4), 0);
    EXPECT_EQ(sequence.count_roots(0.25, 0.5), 1);  // (a, b]: 0.5 counts, 0.25 does not
    EXPECT_EQ(sequence.count_roots(0, 0.25), 1);
}

TEST(SturmSequence, MultipleRootsCountOnceEvenAtTheRootItself) {
    const Polynomial p = polynomial_from_roots(std::vector<double>{0.5, 0.5, 0.5, 0.25, 0.75, 0.75});
    const SturmSequence sequence(p);
    // gcd(p, p') = (t − 0.5)²(t − 0.75) and the square-free part (t − 0.25)(t − 0.5)(t − 0.75), up to scale.
    const Polynomial& repeated = sequence.repeated_factors();
    ASSERT_EQ(repeated.degree(), 3);
    const Polynomial& square_free = sequence.square_free_part();
    ASSERT_EQ(square_free.degree(), 3);
    for (double root : {0.25, 0.5, 0.75}) EXPECT_NEAR(square_free.evaluate(root) / square_free[3], 0, 1e-12);
    EXPECT_NEAR(repeated.evaluate(0.5) / repeated[3], 0, 1e-12);
    EXPECT_NEAR(repeated.evaluate(0.75) / repeated[3], 0, 1e-12);
    EXPECT_EQ(sequence.count_roots(0, 1), 3);
    EXPECT_EQ(sequence.count_roots(0.4, 0.6), 1);
    EXPECT_EQ(sequence.count_roots(0.3, 0.7), 1);
    EXPECT_EQ(sequence.count_roots(0.7, 0.8), 1);
}

TEST(SturmSequence, MembersAreNormalisedAtExtremeScales) {
    for (double scale : {1e-300, 1e300}) {
        const SturmSequence sequence(polynomial_from_roots(std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5}, scale));
        ASSERT_EQ(sequence.size(), 6);
        for (int i = 0; i < sequence.size(); ++i) {
            double largest = 0;
            for (int k = 0; k <= sequence[i].degree(); ++k) largest = std::max(largest, std::abs(sequence[i][k]));
            EXPECT_GE(largest, 1.0);
            EXPECT_LT(largest, 2.0);
        }
        EXPECT_EQ(sequence.count_roots(0, 1), 5);
    }
}

TEST(SturmSequence, MultipleRootsAreReportedOnceAsTangent) {
    for (double multiple_root : {0.5, 0.3}) {
        for (int multiplicity : {2, 3}) {
            std::vector<double> roots_with_multiplicity(multiplicity, multiple_root);
            roots_with_multiplicity.push_back(0.8);
            const PolynomialRoots roots = sturm_roots(polynomial_from_roots(roots_with_multiplicity), 0, 1);
            ASSERT_EQ(roots.size(), 2) << multiple_root << " " << multiplicity;
            EXPECT_NEAR(roots[0].t, multiple_root, 1e-9);
            EXPECT_TRUE(roots[0].tangent);
            EXPECT_NEAR(roots[1].t, 0.8, 1e-12);
            EXPECT_FALSE(roots[1].tangent);
        }
    }
}

}  // namespace
}  // namespace isotrace
