// B-spline bases: spans, partition of unity, known basis values, and rejected knot vectors.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "geometry/curves/knot_vector.h"

namespace isotrace {
namespace {

TEST(KnotVector, ClampedUniformCubicHasKnownBasisValues) {
    const KnotVector knots = KnotVector::clamped_uniform(3, 4);  // one Bézier segment: Bernstein polynomials
    EXPECT_EQ(knots.knots(), (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
    double b[4];
    knots.basis(knots.span(0.25), 0.25, b);
    EXPECT_NEAR(b[0], 0.421875, 1e-15);  // (1 − u)³
    EXPECT_NEAR(b[1], 0.421875, 1e-15);  // 3u(1 − u)²
    EXPECT_NEAR(b[2], 0.140625, 1e-15);  // 3u²(1 − u)
    EXPECT_NEAR(b[3], 0.015625, 1e-15);  // u³
}

TEST(KnotVector, UniformCubicAtAKnotIsOneSixthFourSixthsOneSixth) {
    const KnotVector knots = KnotVector::uniform(3, 6);
    EXPECT_EQ(knots.domain_start(), 3);
    EXPECT_EQ(knots.domain_end(), 6);
    double b[4];
    const int span = knots.span(4);
    EXPECT_EQ(span, 4);
    knots.basis(span, 4, b);
    EXPECT_NEAR(b[0], 1.0 / 6, 1e-15);
    EXPECT_NEAR(b[1], 4.0 / 6, 1e-15);
    EXPECT_NEAR(b[2], 1.0 / 6, 1e-15);
    EXPECT_NEAR(b[3], 0, 1e-15);
}

TEST(KnotVector, NonUniformBasisIsAPartitionOfUnityAndSpansCoverTheDomain) {
    const KnotVector knots(2, {0, 0, 0, 0.1, 0.5, 0.5, 0.9, 1, 1, 1});  // a double interior knot
    EXPECT_EQ(knots.control_count(), 7);
    for (double t = 0; t <= 1.0; t += 1.0 / 64) {
        const double u = knots.to_knot(t);
        const int span = knots.span(u);
        ASSERT_GE(span, 2);
        ASSERT_LE(span, 6);
        EXPECT_LE(knots.knots()[std::size_t(span)], u);
        EXPECT_LT(u, knots.knots()[std::size_t(span) + 1] + (t == 1 ? 1e-12 : 0));
        double b[3];
        knots.basis(span, u, b);
        EXPECT_NEAR(b[0] + b[1] + b[2], 1, 1e-14);
        for (double v : b) EXPECT_GE(v, 0);
    }
    double b[3];
    knots.basis(knots.span(0.5), 0.5, b);  // a double knot of a quadratic: interpolates control point 3
    EXPECT_NEAR(b[0], 1, 1e-15);
}

TEST(KnotVector, AveragedKnotsFollowPieglAndTiller) {
    const KnotVector knots = KnotVector::averaged(3, {0, 0.2, 0.5, 0.6, 1});
    EXPECT_EQ(knots.knots().size(), 9u);
    EXPECT_NEAR(knots.knots()[4], (0.2 + 0.5 + 0.6) / 3, 1e-15);
    EXPECT_EQ(knots.knots()[3], 0);
    EXPECT_EQ(knots.knots()[5], 1);
}

TEST(KnotVector, RejectsBadKnots) {
    EXPECT_THROW(KnotVector(3, {0, 0, 0, 0, 1, 1, 1}), std::invalid_argument);          // too few knots
    EXPECT_THROW(KnotVector(1, {0, 1, 0.5, 2}), std::invalid_argument);                 // decreasing
    EXPECT_THROW(KnotVector(1, {0, 0, 0, 0}), std::invalid_argument);                   // empty domain
    EXPECT_THROW(KnotVector(1, {0, 0, NAN, 1}), std::invalid_argument);                 // not finite
    EXPECT_THROW(KnotVector(-1, {0, 1}), std::invalid_argument);                        // negative degree
    EXPECT_THROW(KnotVector::uniform(KnotVector::kMaxDegree + 1, 40), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
