#include "geometry/polynomial/quadratic_roots.h"

#include <gtest/gtest.h>

namespace isotrace {
namespace {

TEST(QuadraticRoots, TwoRootsAscending) {
    const QuadraticRoots r = quadratic_roots(2, -2, -12);  // 2(s − 3)(s + 2)
    ASSERT_EQ(r.count, 2);
    EXPECT_DOUBLE_EQ(r.roots[0], -2);
    EXPECT_DOUBLE_EQ(r.roots[1], 3);
}

TEST(QuadraticRoots, NoRealRoots) { EXPECT_EQ(quadratic_roots(1, 0, 1).count, 0); }

TEST(QuadraticRoots, DoubleRootCountsOnce) {
    const QuadraticRoots r = quadratic_roots(1, -4, 4);
    ASSERT_EQ(r.count, 1);
    EXPECT_DOUBLE_EQ(r.roots[0], 2);
    const QuadraticRoots at_zero = quadratic_roots(3, 0, 0);
    ASSERT_EQ(at_zero.count, 1);
    EXPECT_EQ(at_zero.roots[0], 0);
}

TEST(QuadraticRoots, LinearAndConstant) {
    const QuadraticRoots r = quadratic_roots(0, 2, -3);
    ASSERT_EQ(r.count, 1);
    EXPECT_DOUBLE_EQ(r.roots[0], 1.5);
    EXPECT_EQ(quadratic_roots(0, 0, 1).count, 0);
}

// The school formula loses the small root to cancellation when b² ≫ 4ac: (s − 1e8)(s − 1e-8) has a root 1e-8
// that (−b + √D)/2a computes with no correct digit; both roots must come out to full relative precision.
TEST(QuadraticRoots, NoCancellationForWidelySeparatedRoots) {
    const QuadraticRoots r = quadratic_roots(1, -(1e8 + 1e-8), 1);
    ASSERT_EQ(r.count, 2);
    EXPECT_NEAR(r.roots[0], 1e-8, 1e-8 * 1e-15);
    EXPECT_NEAR(r.roots[1], 1e8, 1e8 * 1e-15);
    const QuadraticRoots negative = quadratic_roots(1, 1e8 + 1e-8, 1);
    EXPECT_NEAR(negative.roots[0], -1e8, 1e8 * 1e-15);
    EXPECT_NEAR(negative.roots[1], -1e-8, 1e-8 * 1e-15);
}

TEST(QuadraticRoots, CallerDiscriminantIsUsed) {
    // s² − 2: with D given as 8 the roots are ±√2; with D = 0 the double root is at 0.
    const QuadraticRoots r = quadratic_roots_with_discriminant(1, 0, -2, 8);
    ASSERT_EQ(r.count, 2);
    EXPECT_DOUBLE_EQ(r.roots[1], std::sqrt(2.0));
    EXPECT_EQ(quadratic_roots_with_discriminant(1, 0, -2, -1).count, 0);
}

}  // namespace
}  // namespace isotrace
