// NURBS: the exact circle and its derivatives.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "geometry/curves/rational_curve.h"
#include "renderer/math/vec3.h"

namespace isotrace {
namespace {

// The unit circle in the xy plane as a quadratic NURBS of nine control points (Piegl & Tiller Fig. 7.16).
RationalCurve<Vec3d> unit_circle() {
    const double w = std::sqrt(0.5);
    return {KnotVector(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}),
            {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {0, -1, 0}, {1, -1, 0}, {1, 0, 0}},
            {1, w, 1, w, 1, w, 1, w, 1}};
}

TEST(RationalCurve, QuadraticNurbsCircleIsExact) {
    const RationalCurve<Vec3d> circle = unit_circle();
    for (double t = 0; t <= 1; t += 1.0 / 97) {
        const CurveJet<Vec3d> jet = circle.jet(t);
        EXPECT_NEAR(length(jet.value), 1, 1e-15);
        EXPECT_NEAR(dot(jet.value, jet.first), 0, 1e-13);  // tangent ⟂ radius
        // d²|C|²/dt² = 0 ⇒ ⟨C, C''⟩ = −|C'|².
        EXPECT_NEAR(dot(jet.value, jet.second), -dot(jet.first, jet.first), 1e-10 * dot(jet.first, jet.first));
    }
    EXPECT_NEAR(circle(0.125).x, std::sqrt(0.5), 1e-15);  // the middle of each quarter is at 45°
    EXPECT_NEAR(circle(0.125).y, std::sqrt(0.5), 1e-15);
}

TEST(RationalCurve, DerivativesMatchFiniteDifferences) {
    const RationalCurve<Vec3d> circle = unit_circle();
    const double h = 1e-6;
    for (double t : {0.1, 0.3, 0.6, 0.9}) {
        const CurveJet<Vec3d> jet = circle.jet(t);
        const Vec3d first = (circle(t + h) - circle(t - h)) / (2 * h);
        const Vec3d second = (circle.jet(t + h).first - circle.jet(t - h).first) / (2 * h);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(jet.first[k], first[k], 1e-6);
            EXPECT_NEAR(jet.second[k], second[k], 1e-4);
        }
    }
}

TEST(RationalCurve, UnitWeightsGiveThePolynomialCurve) {
    const std::vector<Vec3d> p{{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, -1}};
    const RationalCurve<Vec3d> rational(KnotVector::clamped_uniform(3, 4), p, {1, 1, 1, 1});
    const auto polynomial = bezier_curve(p);
    for (double t : {0.0, 0.3, 0.8}) EXPECT_NEAR(length(rational(t) - polynomial(t)), 0, 1e-15);
}

TEST(RationalCurve, RejectsBadWeights) {
    const std::vector<Vec3d> p{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    const KnotVector knots = KnotVector::clamped_uniform(2, 3);
    EXPECT_THROW(RationalCurve<Vec3d>(knots, p, {1, 0, 1}), std::invalid_argument);
    EXPECT_THROW(RationalCurve<Vec3d>(knots, p, {1, NAN, 1}), std::invalid_argument);
    EXPECT_THROW(RationalCurve<Vec3d>(knots, p, {1, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
