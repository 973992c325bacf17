// SpaceCurve: one type for Bézier, B-spline and NURBS curves in space.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/curves/space_curve.h"

namespace isotrace {
namespace {

TEST(SpaceCurve, BezierInterpolatesItsEndsAndTangentsMatchFiniteDifferences) {
    const SpaceCurve curve = SpaceCurve::bezier({{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 2}});
    EXPECT_EQ(curve(0), Vec3d(0, 0, 0));
    EXPECT_EQ(curve(1), Vec3d(4, 0, 2));
    EXPECT_LT(length(curve.value_and_tangent(0).second - Vec3d(3, 6, 0)), 1e-14);  // 3 (P1 − P0)
    const double h = 1e-6;
    for (double t : {0.1, 0.5, 0.9}) {
        const Vec3d difference = (1 / (2 * h)) * (curve(t + h) - curve(t - h));
        EXPECT_LT(length(curve.value_and_tangent(t).second - difference), 1e-7);
    }
}

TEST(SpaceCurve, NurbsQuarterCircleIsExact) {
    const double w = std::sqrt(0.5);
    const SpaceCurve arc(KnotVector::clamped_uniform(2, 3), {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, w, 1});
    for (double t = 0; t <= 1; t += 0.125) EXPECT_NEAR(length(arc(t)), 1, 1e-15);
    EXPECT_NEAR(arc.polyline_length(1000), std::numbers::pi / 2, 1e-6);
}

TEST(SpaceCurve, RejectsNonFinitePointsAndTooFewPoints) {
    EXPECT_THROW(SpaceCurve::bezier({{0, 0, 0}, {NAN, 0, 0}}), std::invalid_argument);
    EXPECT_THROW(SpaceCurve::bezier({{0, 0, 0}, {INFINITY, 0, 0}}), std::invalid_argument);
    EXPECT_THROW(SpaceCurve::bezier({{0, 0, 0}}), std::invalid_argument);
    EXPECT_THROW(SpaceCurve(KnotVector::clamped_uniform(2, 3), {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {1, 0, 1}),
                 std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
