#include "geometry/curves/shape_preserving_curve.h"

#include <gtest/gtest.h>

#include "geometry/curves/curve_interpolation.h"

namespace isotrace {
namespace {

TEST(ShapePreservingCurve, InterpolatesAndNeverOvershoots) {
    // A step: the interpolating cubic B-spline rings below 1 before it; this curve stays within each interval's values.
    const std::vector<double> t = {0, 0.2, 0.4, 0.6, 0.8, 1}, values = {1, 1, 1, 2, 2, 2};
    const BSplineCurve<double> curve = shape_preserving_curve(values, t);
    for (std::size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(curve(t[k]), values[k], 1e-12);
    double low = 10, high = -10;
    for (int i = 0; i <= 1000; ++i) {
        low = std::min(low, curve(i / 1000.0));
        high = std::max(high, curve(i / 1000.0));
    }
    EXPECT_GE(low, 1 - 1e-12);
    EXPECT_LE(high, 2 + 1e-12);
    const BSplineCurve<double> cubic = interpolate_curve(values, t, 3);
    double cubic_low = 10;
    for (int i = 0; i <= 1000; ++i) cubic_low = std::min(cubic_low, cubic(i / 1000.0));
    EXPECT_LT(cubic_low, 0.99);  // what this curve is for
}

TEST(ShapePreservingCurve, IsC1AtTheKeys) {
    const std::vector<double> t = {0, 0.3, 0.5, 1}, values = {0, 1, 3, 4};
    const BSplineCurve<double> curve = shape_preserving_curve(values, t), slope = curve.derivative();
    const std::vector<double> expected = shape_preserving_slopes(values, t);
    for (std::size_t k = 1; k + 1 < t.size(); ++k) {
        EXPECT_NEAR(slope(t[k] - 1e-9), expected[k], 1e-5);
        EXPECT_NEAR(slope(t[k] + 1e-9), expected[k], 1e-5);
    }
}

TEST(ShapePreservingCurve, PointsInSpaceGoCoordinateByCoordinate) {
    const std::vector<double> t = {0, 0.5, 1};
    const BSplineCurve<Vec3d> curve = shape_preserving_curve(std::vector<Vec3d>{{0, 0, 0}, {1, 2, 0}, {2, 2, 1}}, t);
    EXPECT_NEAR(length(curve(0.5) - Vec3d(1, 2, 0)), 0, 1e-12);
    EXPECT_LE(curve(0.75).y, 2 + 1e-12);  // y is level from 0.5 on: no bulge above it
}

}  // namespace
}  // namespace isotrace
