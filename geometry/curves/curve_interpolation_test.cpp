// Interpolation: through the data, exact for polynomials of the curve's degree, chord-length parameters, and
// closed cubic splines that are C² across the seam.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/curves/curve_interpolation.h"

namespace isotrace {
namespace {

TEST(CurveInterpolation, ChordLengthParametersAreNormalisedCumulativeDistances) {
    const std::vector<double> t = chord_length_parameters({{0, 0, 0}, {3, 0, 0}, {3, 4, 0}, {3, 4, 3}});
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[0], 0);
    EXPECT_NEAR(t[1], 0.3, 1e-15);
    EXPECT_NEAR(t[2], 0.7, 1e-15);
    EXPECT_EQ(t[3], 1);
    EXPECT_THROW(chord_length_parameters({{0, 0, 0}, {0, 0, 0}}), std::invalid_argument);
    EXPECT_THROW(chord_length_parameters({{0, 0, 0}}), std::invalid_argument);
    EXPECT_THROW(chord_length_parameters({{0, 0, 0}, {NAN, 0, 0}}), std::invalid_argument);
}

TEST(CurveInterpolation, CubicPassesThroughThePointsAndReproducesCubics) {
    const std::vector<double> t{0, 0.1, 0.35, 0.5, 0.8, 1};
    auto cubic = [](double x) { return 2 - x + 3 * x * x - 5 * x * x * x; };
    std::vector<double> values;
    for (double x : t) values.push_back(cubic(x));
    const BSplineCurve<double> curve = interpolate_curve(values, t, 3);
    EXPECT_EQ(curve.degree(), 3);
    for (std::size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(curve(t[k]), values[k], 1e-13);
    // The spline space holds every cubic and interpolation is unique, so the cubic comes back everywhere.
    for (double x = 0; x <= 1; x += 0.01) EXPECT_NEAR(curve(x), cubic(x), 1e-12);
}

TEST(CurveInterpolation, QuadraticAndLoweredDegrees) {
    const std::vector<double> t{0, 0.4, 1};
    const BSplineCurve<double> quadratic = interpolate_curve(std::vector<double>{1, 0, 3}, t, 2);
    EXPECT_EQ(quadratic.degree(), 2);
    EXPECT_NEAR(quadratic(0.4), 0, 1e-14);
    const BSplineCurve<double> line = interpolate_curve(std::vector<double>{1, 3}, {0, 1}, 3);
    EXPECT_EQ(line.degree(), 1);  // two points: the degree drops to 1
    EXPECT_NEAR(line(0.25), 1.5, 1e-15);
    EXPECT_THROW(interpolate_curve(std::vector<double>{1}, {0}, 3), std::invalid_argument);
    EXPECT_THROW(interpolate_curve(std::vector<double>{1, 2, 3}, {0, 0.5, 0.5}, 3), std::invalid_argument);
    EXPECT_THROW(interpolate_curve(std::vector<double>{1, 2, 3}, {0, 0.5, 0.9}, 3), std::invalid_argument);
}

TEST(CurveInterpolation, SpacePointsWithChordLengths) {
    const std::vector<Vec3d> points{{0, 0, 0}, {1, 1, 0}, {2, 0, 1}, {3, 1, 1}, {4, 0, 0}};
    const std::vector<double> t = chord_length_parameters(points);
    const BSplineCurve<Vec3d> curve = interpolate_curve(points, t, 3);
    for (std::size_t k = 0; k < points.size(); ++k) EXPECT_NEAR(length(curve(t[k]) - points[k]), 0, 1e-14);
}

TEST(CurveInterpolation, ClosedCubicInterpolatesAndIsC2AcrossTheSeam) {
    const int m = 12;
    std::vector<double> samples;
    for (int j = 0; j < m; ++j) samples.push_back(1 + 0.3 * std::cos(2 * std::numbers::pi * j / m) + (j == 4 ? 0.2 : 0));
    const PeriodicCurve<double> curve = interpolate_periodic_cubic(samples);
    for (int j = 0; j < m; ++j) EXPECT_NEAR(curve(double(j) / m), samples[std::size_t(j)], 1e-14);
    const auto first = curve.derivative();
    const auto second = first.derivative();
    const double e = 1e-9;  // just before and after the seam (and any other knot) the values agree
    EXPECT_NEAR(curve(-e), curve(e), 1e-8);
    EXPECT_NEAR(first(-e), first(e), 1e-7);
    EXPECT_NEAR(second(-e), second(e), 1e-6);
    EXPECT_NEAR(curve(1.25), curve(0.25), 1e-15);  // periodic with period 1
}

TEST(CurveInterpolation, ClosedCubicConvergesToASmoothPeriodicFunction) {
    // Fourth-order convergence: doubling the samples divides the error by about 16.
    auto error_with = [](int m) {
        std::vector<double> samples;
        for (int j = 0; j < m; ++j) samples.push_back(std::sin(2 * std::numbers::pi * j / m));
        const PeriodicCurve<double> curve = interpolate_periodic_cubic(samples);
        double worst = 0;
        for (double s = 0; s < 1; s += 1.0 / 997) worst = std::max(worst, std::abs(curve(s) - std::sin(2 * std::numbers::pi * s)));
        return worst;
    };
    const double coarse = error_with(16), fine = error_with(32);
    EXPECT_LT(coarse, 1e-3);
    EXPECT_GT(coarse / fine, 12);
    EXPECT_THROW(interpolate_periodic_cubic(std::vector<double>{1, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
