// Bézier and B-spline curves: values against closed forms, linear precision, derivatives against finite
// differences and closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "geometry/curves/bspline_curve.h"
#include "renderer/math/vec3.h"

namespace isotrace {
namespace {

void expect_near(const Vec3d& a, const Vec3d& b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(BSplineCurve, CubicBezierMatchesTheBernsteinForm) {
    const std::vector<Vec3d> p{{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, -1}};
    const auto curve = bezier_curve(p);
    for (double t : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
        const double s = 1 - t;
        const Vec3d expected = s * s * s * p[0] + 3 * s * s * t * p[1] + 3 * s * t * t * p[2] + t * t * t * p[3];
        expect_near(curve(t), expected, 1e-14);
    }
    const auto velocity = curve.derivative();
    expect_near(velocity(0), 3.0 * (p[1] - p[0]), 1e-14);  // the hodograph's end values
    expect_near(velocity(1), 3.0 * (p[3] - p[2]), 1e-14);
    const auto acceleration = velocity.derivative();
    expect_near(acceleration(0), 6.0 * (p[2] - 2.0 * p[1] + p[0]), 1e-13);
}

TEST(BSplineCurve, NonUniformCurveReproducesTheLineThroughItsGrevilleAbscissae) {
    // Linear precision: control values ξ_i = (u_{i+1} + … + u_{i+p}) / p give C(u) = u.
    const KnotVector knots(3, {0, 0, 0, 0, 0.15, 0.4, 0.45, 0.8, 1, 1, 1, 1});
    std::vector<double> greville;
    for (int i = 0; i < knots.control_count(); ++i)
        greville.push_back((knots.knots()[std::size_t(i) + 1] + knots.knots()[std::size_t(i) + 2] +
                            knots.knots()[std::size_t(i) + 3]) / 3);
    const BSplineCurve<double> curve(knots, greville);
    const auto slope = curve.derivative();
    const auto bend = slope.derivative();
    for (double t = 0; t <= 1; t += 0.05) {
        EXPECT_NEAR(curve(t), t, 1e-14);
        EXPECT_NEAR(slope(t), 1, 1e-12);
        EXPECT_NEAR(bend(t), 0, 1e-10);
    }
}

TEST(BSplineCurve, NormalisedParameterMapsOntoAnUnclampedDomain) {
    // Uniform cubic over knots 0…9 (6 controls): domain [3, 6]; t = 1/3 is the knot 4, where the value is
    // (P1 + 4 P2 + P3) / 6 and the derivative with respect to t is 3 · (P3 − P1) / 2.
    const std::vector<double> p{0, 1, 5, 2, 7, 3};
    const BSplineCurve<double> curve(KnotVector::uniform(3, 6), p);
    EXPECT_NEAR(curve(1.0 / 3), (p[1] + 4 * p[2] + p[3]) / 6, 1e-14);
    EXPECT_NEAR(curve.derivative()(1.0 / 3), 3 * (p[3] - p[1]) / 2, 1e-13);
}

TEST(BSplineCurve, DerivativesMatchFiniteDifferences) {
    const KnotVector knots(4, {0, 0, 0, 0, 0, 0.3, 0.3, 0.7, 1, 1, 1, 1, 1});
    const BSplineCurve<Vec3d> curve(knots, {{0, 0, 0}, {1, 3, 0}, {2, -1, 1}, {4, 4, 2}, {5, 0, 0}, {7, 2, 1},
                                            {8, 1, 3}, {9, 0, 0}});
    const DifferentiableCurve<Vec3d> jet(curve);
    const double h = 1e-6;
    for (double t : {0.05, 0.2, 0.5, 0.65, 0.95}) {
        expect_near(jet.first(t), (curve(t + h) - curve(t - h)) / (2 * h), 1e-5);
        expect_near(jet.second(t), (jet.first(t + h) - jet.first(t - h)) / (2 * h), 1e-4);
    }
}

TEST(BSplineCurve, ClampsTheParameterAndRejectsMismatchedControlPoints) {
    const auto line = bezier_curve(std::vector<double>{2, 5});
    EXPECT_EQ(line(-1), 2);
    EXPECT_EQ(line(2), 5);
    EXPECT_THROW(BSplineCurve<double>(KnotVector::clamped_uniform(3, 5), {1, 2, 3}), std::invalid_argument);
    EXPECT_THROW(bezier_curve(std::vector<double>{}), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
