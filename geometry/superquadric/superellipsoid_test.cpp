// The superellipsoid alone: the gauge against the paper's inside-outside function, overflow safety, the
// parametric surface, normals against finite differences and at the coordinate planes, which exponents make the ellipsoid.
#include "geometry/superquadric/superellipsoid.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iterator>
#include <optional>
#include <random>

namespace isotrace {
namespace {

double direct_inside_outside(const Superellipsoid& s, const Vec3d& p) {
    const double a = std::pow(std::abs(p.x) / s.radii().x, 2 / s.east_west()) +
                     std::pow(std::abs(p.y) / s.radii().y, 2 / s.east_west());
    return std::pow(a, s.east_west() / s.north_south()) + std::pow(std::abs(p.z) / s.radii().z, 2 / s.north_south());
}

// The paper's F from the gauge: F = G^(2/ε1).
double paper_inside_outside(const Superellipsoid& s, const Vec3d& p) { return std::pow(s.gauge(p), 2 / s.north_south()); }

TEST(SuperquadricSuperellipsoid, GaugeIsTheInsideOutsideFunctionToThePowerEpsilonOverTwo) {
    std::mt19937 random(1);
    std::uniform_real_distribution<double> unit(-1, 1), exponent(0.1, 4);
    for (int i = 0; i < 2000; ++i) {
        const Superellipsoid s{{1 + unit(random) * 0.5, 1.5 + unit(random), 0.8 + 0.5 * unit(random)}, exponent(random),
                               exponent(random)};
        const Vec3d p{1.5 * unit(random), 2 * unit(random), unit(random)};
        const double expected = direct_inside_outside(s, p);
        EXPECT_NEAR(paper_inside_outside(s, p), expected, 1e-12 * expected) << i;
        EXPECT_EQ(s.gauge(p) < 1, expected < 1) << i;
    }
}

TEST(SuperquadricSuperellipsoid, GaugeIsFiniteFarAwayOnThePlanesAndHomogeneous) {
    for (double e1 : {0.02, 0.5, 1.0, 2.0, 4.0})
        for (double e2 : {0.02, 1.0, 4.0}) {
            const Superellipsoid s{{1, 2, 3}, e1, e2};
            for (const Vec3d& p : {Vec3d(1e300, 1e300, 1e300), Vec3d(0, 0, 1e300), Vec3d(1e-300, 0, 0), Vec3d(0, 0, 0),
                                   Vec3d(0, 2, 0), Vec3d(-1e200, 0, 1e-200)}) {
                const double g = s.gauge(p);
                EXPECT_TRUE(std::isfinite(g)) << e1 << " " << e2;
                EXPECT_GE(g, 0);
            }
            // Degree 1: G(λp) = λ G(p), even where F = G^(2/ε1) itself would overflow.
            const Vec3d p(0.3, -0.7, 1.1);
            EXPECT_NEAR(s.gauge(p * 1e250), 1e250 * s.gauge(p), 1e-12 * 1e250 * s.gauge(p));
            EXPECT_NEAR(s.gauge(Vec3d(0, 2, 0)), 1.0, 1e-15);
            EXPECT_NEAR(s.gauge(Vec3d(0, 0, -3)), 1.0, 1e-15);
        }
}

TEST(SuperquadricSuperellipsoid, ParametricSurfacePointsHaveUnitGaugeAndTheGaugeRangeBoundsIt) {
    std::mt19937 random(2);
    std::uniform_real_distribution<double> eta(-1.5707963, 1.5707963), omega(-3.14159265, 3.14159265), exponent(0.02, 4);
    for (int i = 0; i < 3000; ++i) {
        const Superellipsoid s{{0.5, 1.5, 2}, exponent(random), exponent(random)};
        const double e = eta(random), w = omega(random);
        const Vec3d p = s.surface_point(e, w);
        EXPECT_NEAR(s.gauge(p), 1.0, 1e-12) << i;
        const IntervalBox around{{std::abs(p.x) * 0.9, std::abs(p.x) * 1.1}, {std::abs(p.y) * 0.9, std::abs(p.y)},
                                 {std::abs(p.z), std::abs(p.z) * 1.2}};
        const Interval range = s.gauge_range(around);
        EXPECT_LE(range.lo, 1.0 + 1e-12);
        EXPECT_GE(range.hi, 1.0 - 1e-12);
    }
}

// The gauge in long double: the nested p-norm ‖(‖(u, v)‖_{2/ε2}, w)‖_{2/ε1} as written.
long double exact_gauge(const Superellipsoid& s, const Vec3d& p) {
    const long double p1 = 2.0L / s.north_south(), p2 = 2.0L / s.east_west();
    const long double u = std::abs(p.x) / (long double)s.radii().x, v = std::abs(p.y) / (long double)s.radii().y,
                      w = std::abs(p.z) / (long double)s.radii().z;
    const long double h = std::pow(std::pow(u, p2) + std::pow(v, p2), 1 / p2);
    return std::pow(std::pow(h, p1) + std::pow(w, p1), 1 / p1);
}

// The range over a box of magnitudes holds the exact gauge and the computed one at every point of the box, for
// whole exponents (repeated squaring and polynomial roots) and fractional ones (pow) alike.
TEST(SuperquadricSuperellipsoid, TheGaugeRangeHoldsTheExactAndTheComputedGauge) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(0, 1), exponent(0.02, 4);
    const double whole[] = {2.0 / 3, 0.5, 0.4, 0.2, 0.1, 2.0 / 7, 0.02};
    for (int i = 0; i < 4000; ++i) {
        const double e1 = i % 2 ? exponent(random) : whole[i / 2 % 7], e2 = i % 3 ? exponent(random) : whole[i / 3 % 7];
        const Superellipsoid s{{0.5 + unit(random), 0.5 + unit(random), 0.5 + unit(random)}, e1, e2};
        const Vec3d corner{1.2 * unit(random), 1.2 * unit(random), 1.2 * unit(random)};
        const Vec3d size = Vec3d(unit(random), unit(random), unit(random)) * (i % 4 ? 1e-9 : 0.1);
        const IntervalBox box{{corner.x, corner.x + size.x}, {corner.y, corner.y + size.y}, {corner.z, corner.z + size.z}};
        const Interval range = s.gauge_range(box);
        for (int k = 0; k < 8; ++k) {
            const Vec3d p = k == 0 ? box.lower() : k == 1 ? box.upper()
                                   : corner + Vec3d(size.x * unit(random), size.y * unit(random), size.z * unit(random));
            const long double exact = exact_gauge(s, p);
            EXPECT_LE(range.lo, exact) << i << " e " << e1 << " " << e2;
            EXPECT_GE(range.hi, exact) << i << " e " << e1 << " " << e2;
            EXPECT_TRUE(range.contains(s.gauge(p))) << i << " e " << e1 << " " << e2;
        }
    }
}

Vec3d finite_difference_gradient(const Superellipsoid& s, const Vec3d& p, double h) {
    Vec3d g;
    for (int k = 0; k < 3; ++k) {
        Vec3d a = p, b = p;
        a[k] -= h;
        b[k] += h;
        g[k] = (s.gauge(b) - s.gauge(a)) / (2 * h);
    }
    return g;
}

TEST(SuperquadricSuperellipsoid, NormalsFollowTheGradient) {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> eta(-1.4, 1.4), omega(-3.0, 3.0), exponent(0.1, 4);
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const Superellipsoid s{{1, 0.7, 1.3}, exponent(random), exponent(random)};
        const double e = eta(random), w = omega(random);
        const Vec3d p = s.surface_point(e, w);
        // Stay away from the planes, where the gradient may be unbounded.
        if (std::min({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) < 0.05) continue;
        const Vec3d expected = normalize(finite_difference_gradient(s, p, 1e-7));
        const Vec3d n = s.normal(p);
        EXPECT_NEAR(length(n), 1.0, 1e-12);
        EXPECT_GT(dot(n, expected), 1 - 1e-6) << i << " e " << s.north_south() << " " << s.east_west();
        ++checked;
    }
    EXPECT_GT(checked, 500);
}

// The gauge along a direction gives the gauge bit for bit and its directional derivative (the Newton steps of the
// ray search), checked by central differences away from the coordinate planes; where the derivative is unbounded
// (a zero coordinate with an exponent above 2) it is NaN, never a finite wrong value.
TEST(SuperquadricSuperellipsoid, GaugeAlongADirectionHasTheGaugesDerivative) {
    std::mt19937 random(41);
    std::uniform_real_distribution<double> unit(-1, 1), exponent(0.05, 4);
    for (int i = 0; i < 2000; ++i) {
        const Superellipsoid s{{0.5 + std::abs(unit(random)), 0.5 + std::abs(unit(random)), 0.5 + std::abs(unit(random))},
                               exponent(random), exponent(random)};
        const Vec3d p{unit(random), unit(random), unit(random)}, d{unit(random), unit(random), unit(random)};
        if (std::min({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) < 1e-2) continue;
        const ValueAndDerivative along = s.gauge_along(p, d);
        EXPECT_EQ(along.value, s.gauge(p)) << i;
        const double h = 1e-6, expected = (s.gauge(p + d * h) - s.gauge(p - d * h)) / (2 * h);
        EXPECT_NEAR(along.derivative, expected, 1e-5 * (1 + std::abs(expected))) << i;
    }
    const Superellipsoid star{{1, 1, 1}, 3, 3};
    EXPECT_TRUE(std::isnan(star.gauge_along({0.3, 0, 0.2}, {0.1, 1, 0.3}).derivative));
    const Superellipsoid ball{{1, 1, 1}, 1, 1};
    EXPECT_NEAR(ball.gauge_along({0.6, 0, 0}, {0, 1, 0}).derivative, 0, 1e-15);  // tangent to the sphere's level set
    EXPECT_NEAR(ball.gauge_along({0.6, 0, 0}, {-2, 0, 0}).derivative, -2, 1e-15);
}

// (part/whole)^(p−1) in long double, with its limits where the part is 0 (NaN where it is unbounded).
long double share_power(long double part, long double whole, long double p) {
    if (part == 0) return p > 1 ? 0 : p == 1 ? 1 : NAN;
    return std::pow(part / whole, p - 1);
}

// ∂G/∂x, ∂G/∂y, ∂G/∂z in long double: (h/G)^(p1−1)·(u/h)^(p2−1)/a1, ..., (w/G)^(p1−1)/a3. Unlike gauge_along's
// derivative it keeps the digits of a small share's power below 1's rounding.
std::array<long double, 3> long_double_gradient(const Superellipsoid& s, const Vec3d& q) {
    const long double p1 = 2.0L / s.north_south(), p2 = 2.0L / s.east_west();
    const long double u = std::abs(q.x) / (long double)s.radii().x, v = std::abs(q.y) / (long double)s.radii().y,
                      w = std::abs(q.z) / (long double)s.radii().z;
    const long double h = std::pow(std::pow(u, p2) + std::pow(v, p2), 1 / p2);
    const long double g = std::pow(std::pow(h, p1) + std::pow(w, p1), 1 / p1);
    const long double outer = share_power(h, g, p1);
    return {std::copysign(outer * share_power(u, h, p2) / s.radii().x, q.x),
            std::copysign(outer * share_power(v, h, p2) / s.radii().y, q.y),
            std::copysign(share_power(w, g, p1) / s.radii().z, q.z)};
}

// The gradient bound over a box holds every partial derivative inside the box (boxes that straddle coordinate
// planes included), and over a box shrunk to a point it is the gradient there; for fractional exponents and for
// the whole p = 2/ε whose powers and roots take other paths (NormExponent).
TEST(SuperquadricSuperellipsoid, TheGaugeTakenWithTheDifferenceIsTheGaugeBitForBit) {
    std::mt19937 random(9);
    std::uniform_real_distribution<double> unit(-1, 1);
    const std::array<std::array<double, 2>, 4> exponents{{{0.3, 2.5}, {3.5, 0.05}, {1, 3.5}, {2.5, 0.3}}};
    for (const auto& [north_south, east_west] : exponents) {
        const Superellipsoid s{{0.7, 1.1, 0.9}, north_south, east_west};
        for (int i = 0; i < 500; ++i) {
            const Vec3d p{1.2 * unit(random), 1.2 * unit(random), i % 5 == 0 ? 0.0 : 1.2 * unit(random)};
            EXPECT_EQ(s.gauge_and_difference(p, s.rates_along({unit(random), unit(random), unit(random)})).gauge, s.gauge(p));
        }
    }
}

TEST(SuperquadricSuperellipsoid, TheGradientRangeHoldsThePartialDerivativesAndIsExactAtAPoint) {
    std::mt19937 random(43);
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1), exponent(0.05, 4);
    const double whole_p_epsilons[] = {2, 1, 0.5, 0.4, 0.25, 0.2, 0.1, 0.04};
    std::uniform_int_distribution<int> pick(0, std::size(whole_p_epsilons) - 1);
    const auto random_exponent = [&](int i) { return i % 3 == 0 ? whole_p_epsilons[pick(random)] : exponent(random); };
    const Vec3d axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    int checked = 0;
    for (int i = 0; i < 3000; ++i) {
        const Superellipsoid s{{0.5 + fraction(random), 0.5 + fraction(random), 0.5 + fraction(random)},
                               random_exponent(i), random_exponent(i)};
        const Vec3d corner{unit(random), unit(random), unit(random)};
        const Vec3d size = Vec3d(fraction(random), fraction(random), fraction(random)) * (i % 2 ? 0.02 : 0.6);
        const IntervalBox box{{corner.x, corner.x + size.x}, {corner.y, corner.y + size.y}, {corner.z, corner.z + size.z}};
        const IntervalBox range = s.gradient_range(box);
        const Interval components[3] = {range.x, range.y, range.z};
        for (int k = 0; k < 20; ++k) {
            const Vec3d p = corner + Vec3d(size.x * fraction(random), size.y * fraction(random), size.z * fraction(random));
            const std::array<long double, 3> gradient = long_double_gradient(s, p);
            for (int axis = 0; axis < 3; ++axis) {
                const double partial = double(gradient[axis]);
                if (!std::isfinite(partial)) continue;
                const Interval bound = components[axis];
                const double tolerance = 1e-12 * std::max(std::abs(bound.lo), std::abs(bound.hi)) + 1e-300;
                EXPECT_GE(partial, bound.lo - tolerance) << i << " axis " << axis;
                EXPECT_LE(partial, bound.hi + tolerance) << i << " axis " << axis;
                ++checked;
            }
        }
        const IntervalBox point{{corner.x, corner.x}, {corner.y, corner.y}, {corner.z, corner.z}};
        const IntervalBox at_point = s.gradient_range(point);
        const Interval point_components[3] = {at_point.x, at_point.y, at_point.z};
        for (int axis = 0; axis < 3; ++axis) {
            const double partial = s.gauge_along(corner, axes[axis]).derivative;
            if (std::isnan(partial)) continue;
            EXPECT_NEAR(point_components[axis].lo, partial, 1e-6 * std::abs(partial) + 1e-12) << i << " axis " << axis;
            EXPECT_NEAR(point_components[axis].hi, partial, 1e-6 * std::abs(partial) + 1e-12) << i << " axis " << axis;
        }
    }
    EXPECT_GT(checked, 100000);
}

TEST(SuperquadricSuperellipsoid, NormalsOnTheCoordinatePlanesAreTheLimits) {
    for (double e1 : {0.02, 0.5, 1.0, 2.0, 3.0, 4.0})
        for (double e2 : {0.02, 0.5, 1.0, 2.0, 3.0, 4.0}) {
            const Superellipsoid s{{1, 2, 3}, e1, e2};
            for (const Vec3d& p : {Vec3d(1, 0, 0), Vec3d(0, 2, 0), Vec3d(0, 0, 3), Vec3d(0, 0, -3),
                                   s.surface_point(0.7, 1.5707963267948966), s.surface_point(0, 0.6)}) {
                const Vec3d n = s.normal(p);
                ASSERT_TRUE(is_finite(n)) << e1 << " " << e2;
                EXPECT_NEAR(length(n), 1.0, 1e-12);
                EXPECT_GT(dot(n, p), 0) << "outward at " << p.x << " " << p.y << " " << p.z;
            }
            // The axis ends of a shape that is smooth there (exponents < 2) have the axis as normal.
            if (e1 < 2 && e2 < 2) {
                EXPECT_NEAR(s.normal({1, 0, 0}).x, 1.0, 1e-12);
                EXPECT_NEAR(s.normal({0, 0, -3}).z, -1.0, 1e-12);
            }
        }
    // The ellipsoid's normal on x = 0 has no x component; the octahedron's is the face normal of the x > 0 side.
    const Vec3d on_plane(0, 1, 1.5);
    EXPECT_NEAR((Superellipsoid{{1, 2, 3}, 1, 1}).normal(on_plane * (1 / std::sqrt(0.5))).x, 0.0, 1e-15);
    const Vec3d face = Superellipsoid{{1, 1, 1}, 2, 2}.normal({0, 0.5, 0.5});
    EXPECT_NEAR(dot(face, normalize(Vec3d(1, 1, 1))), 1.0, 1e-12);
}

// The normal is the long-double gradient's direction to 10⁻¹², also a hair off the coordinate planes (where a share's
// power is far below 1's rounding) and on them (where the partials vanish or are unbounded, and the normal is their
// limit), over the whole exponent range. Not to a few ulps: 10⁻³⁰⁰ off a plane a share's power can be subnormal, and
// a thread that flushes subnormals to zero (as Embree's callers may) loses a component of 10⁻¹³.
TEST(SuperquadricSuperellipsoid, NormalsAreTheGradientsDirection) {
    std::mt19937 random(47);
    std::uniform_real_distribution<double> eta(-1.5, 1.5), omega(-3.1, 3.1), fraction(0, 1),
        exponent(Superellipsoid::kMinExponent, Superellipsoid::kMaxExponent);
    const double offsets[] = {0, 1e-300, 1e-150, 1e-30, 1e-9, 1e-3};
    int checked = 0, limits = 0;
    for (int i = 0; i < 4000; ++i) {
        const Superellipsoid s{{0.5 + fraction(random), 0.5 + fraction(random), 0.5 + fraction(random)},
                               exponent(random), exponent(random)};
        const double latitude = eta(random), longitude = omega(random);
        Vec3d p = s.surface_point(latitude, longitude);
        if (i % 2) p[i / 2 % 3] = offsets[i / 6 % std::size(offsets)];  // near or on a coordinate plane
        if (max_component(abs(p)) == 0) continue;
        const Vec3d n = s.normal(p);
        ASSERT_TRUE(is_finite(n)) << i;
        EXPECT_NEAR(length(n), 1.0, 1e-15) << i;
        const std::array<long double, 3> gradient = long_double_gradient(s, p);
        const long double size = std::sqrt(gradient[0] * gradient[0] + gradient[1] * gradient[1] +
                                           gradient[2] * gradient[2]);
        // An unbounded partial (NaN): the normal leans towards its axis when it is one. (The limit is the axis
        // itself; for exponents a hair above 2 the normal's floored logarithms fall short of it.)
        if (std::isnan(double(size))) {
            int unbounded = 0, axis_of = 0;
            for (int axis = 0; axis < 3; ++axis)
                if (std::isnan(double(gradient[axis]))) ++unbounded, axis_of = axis;
            if (unbounded == 1) { EXPECT_EQ(std::abs(n[axis_of]), max_component(abs(n))) << i; }
            ++limits;
            continue;
        }
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_NEAR(n[axis], double(gradient[axis] / size), 1e-12)
                << i << " axis " << axis << " e " << s.north_south() << " " << s.east_west();
        ++checked;
    }
    EXPECT_GT(checked, 3000);
    EXPECT_GT(limits, 20);
}

// A random superellipsoid over the whole exponent range and a segment between two random points of its box.
struct RandomSegment {
    Superellipsoid shape;
    Vec3d start, direction;
    double length;
};

RandomSegment random_segment(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(-1, 1), exponent(Superellipsoid::kMinExponent, Superellipsoid::kMaxExponent);
    const Superellipsoid s{{1 + unit(random) * 0.5, 1.5 + unit(random), 0.8 + 0.5 * unit(random)}, exponent(random),
                           exponent(random)};
    const Vec3d& r = s.radii();
    const Vec3d start{r.x * unit(random), r.y * unit(random), r.z * unit(random)};
    const Vec3d end{r.x * unit(random), r.y * unit(random), r.z * unit(random)};
    return {s, start, normalize(end - start), length(end - start)};
}

TEST(SuperquadricSuperellipsoid, TheEnclosingStretchHoldsEveryPointOfTheSolidAlongTheSegment) {
    std::mt19937 random(7);
    int inside = 0, trimmed = 0;
    for (int i = 0; i < 3000; ++i) {
        const auto [s, start, direction, length] = random_segment(random);
        const std::optional<Interval> stretch = s.enclosing_stretch(start, direction, length);
        for (int k = 0; k <= 400; ++k) {
            const double t = k == 400 ? length : length * k / 400;
            if (s.gauge(start + direction * t) > 1) continue;
            ++inside;
            ASSERT_TRUE(stretch) << i;
            EXPECT_TRUE(stretch->contains(t)) << i << " t " << t;
        }
        if (!stretch) continue;
        // Where the stretch ends inside the segment, the gauge there exceeds 1 by more than its rounding.
        for (const double end_t : {stretch->lo, stretch->hi}) {
            if (end_t == 0 || end_t == length) continue;
            ++trimmed;
            EXPECT_GT(s.gauge(start + direction * end_t), 1 + 1e-12) << i;
        }
    }
    EXPECT_GT(inside, 10000);
    EXPECT_GT(trimmed, 1000);
}

TEST(SuperquadricSuperellipsoid, TheInscribedStretchLiesInsideTheSolid) {
    std::mt19937 random(11);
    int inside = 0;
    for (int i = 0; i < 3000; ++i) {
        const auto [s, start, direction, length] = random_segment(random);
        const std::optional<Interval> stretch = s.inscribed_stretch(start, direction, length);
        if (!stretch) continue;
        for (int k = 0; k <= 100; ++k) {
            const double t = k == 100 ? stretch->hi : stretch->lo + (stretch->hi - stretch->lo) * k / 100;
            ++inside;
            EXPECT_LT(s.gauge(start + direction * t), 1 - 1e-12) << i << " t " << t;
        }
    }
    EXPECT_GT(inside, 10000);
    // A sphere's inscribed ellipsoid is the sphere itself.
    const std::optional<Interval> chord = Superellipsoid({1, 1, 1}, 1, 1).inscribed_stretch({-1, 0.6, 0}, {1, 0, 0}, 2);
    ASSERT_TRUE(chord);
    EXPECT_NEAR(chord->lo, 0.2, 1e-7);
    EXPECT_NEAR(chord->hi, 1.8, 1e-7);
}

// The round forms hold the solid turned about z by any angle (a twist turns each height by its own), and their
// inscribed ellipsoid lies within it at every turn.
TEST(SuperquadricSuperellipsoid, TheRoundQuadricsHoldTheSolidTurnedAboutZ) {
    using QuadricForm = Superellipsoid::QuadricForm;
    std::mt19937 random(13);
    std::uniform_real_distribution<double> angle(-4, 4);
    const auto turned = [](const Vec3d& p, double a) {
        return Vec3d{p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a), p.z};
    };
    int inside = 0, within = 0;
    for (int i = 0; i < 3000; ++i) {
        const auto [s, start, direction, length] = random_segment(random);
        // The segment in the turned frame, which reaches beyond the box's corners.
        const Vec3d wide_start = start * 1.4;
        const std::optional<Interval> around = s.enclosing_stretch(wide_start, direction, length, QuadricForm::RoundAboutZ);
        const std::optional<Interval> inner = s.inscribed_stretch(wide_start, direction, length, QuadricForm::RoundAboutZ);
        for (int k = 0; k <= 200; ++k) {
            const double t = k == 200 ? length : length * k / 200;
            const Vec3d q = wide_start + direction * t;
            const double a = angle(random);
            if (s.gauge(turned(q, a)) <= 1) {
                ++inside;
                ASSERT_TRUE(around) << i;
                EXPECT_TRUE(around->contains(t)) << i << " t " << t;
            }
            if (inner && inner->contains(t)) {
                ++within;
                EXPECT_LT(s.gauge(turned(q, a)), 1 - 1e-12) << i << " t " << t;
            }
        }
    }
    EXPECT_GT(inside, 3000);
    EXPECT_GT(within, 3000);
    // Radii 1 and 2 across z: the round cylinder has the larger radius, the inscribed sphere the smaller.
    const Superellipsoid oval{{1, 2, 1}, 1, 1};
    EXPECT_TRUE(oval.enclosing_stretch({-3, 1.9, 0}, {1, 0, 0}, 6, QuadricForm::RoundAboutZ));
    EXPECT_FALSE(oval.enclosing_stretch({-3, 2.1, 0}, {1, 0, 0}, 6, QuadricForm::RoundAboutZ));
    EXPECT_TRUE(oval.inscribed_stretch({-3, 0.9, 0}, {1, 0, 0}, 6, QuadricForm::RoundAboutZ));
    EXPECT_FALSE(oval.inscribed_stretch({-3, 1.1, 0}, {1, 0, 0}, 6, QuadricForm::RoundAboutZ));
}

TEST(SuperquadricSuperellipsoid, TheEnclosingStretchIsTheChordOfASphereAndOfARoundCylinder) {
    const Superellipsoid sphere{{1, 1, 1}, 1, 1}, cylinder{{1, 1, 1}, Superellipsoid::kMinExponent, 1};
    for (const Superellipsoid* s : {&sphere, &cylinder}) {
        // Along x at height 0.6 the chord is x in [-0.8, 0.8].
        const std::optional<Interval> chord = s->enclosing_stretch({-1, 0.6, 0}, {1, 0, 0}, 2);
        ASSERT_TRUE(chord);
        EXPECT_NEAR(chord->lo, 0.2, 1e-7);
        EXPECT_NEAR(chord->hi, 1.8, 1e-7);
        EXPECT_FALSE(s->enclosing_stretch({-1, 1.0001, 0}, {1, 0, 0}, 2));
        EXPECT_TRUE(s->enclosing_stretch({-1, 0.9999, 0}, {1, 0, 0}, 2));
    }
    // Along the cylinder's axis, inside it: the whole segment; beside it, nothing.
    const std::optional<Interval> axis = cylinder.enclosing_stretch({0.5, 0, -1}, {0, 0, 1}, 2);
    ASSERT_TRUE(axis);
    EXPECT_EQ(axis->lo, 0);
    EXPECT_EQ(axis->hi, 2);
    EXPECT_FALSE(cylinder.enclosing_stretch({0.8, 0.8, -1}, {0, 0, 1}, 2));
}

TEST(SuperquadricSuperellipsoid, OnlyBothExponentsOneMakeTheEllipsoid) {
    EXPECT_TRUE((Superellipsoid{{1, 2, 0.5}, 1, 1}).is_ellipsoid());
    EXPECT_FALSE((Superellipsoid{{1, 1, 1}, 0.5, 0.5}).is_ellipsoid());
    EXPECT_FALSE((Superellipsoid{{1, 1, 1}, 1, 0.5}).is_ellipsoid());
    EXPECT_FALSE((Superellipsoid{{1, 1, 1}, 2, 1}).is_ellipsoid());
    EXPECT_FALSE((Superellipsoid{{1, 1, 1}, 1, std::nextafter(1.0, 2.0)}).is_ellipsoid());
}

}  // namespace
}  // namespace isotrace
