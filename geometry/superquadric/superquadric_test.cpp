// Ray queries of single superquadrics against closed forms (ellipsoid, even powers' polynomials, octahedron, the box
// limit), the first-crossing guarantee on random deformed shapes (every hit is on the surface, no earlier sign
// change), identities of the deformations, normals against finite differences, and conservative bounds.
#include "geometry/superquadric/superquadric.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <random>
#include <utility>

#include "geometry/superquadric/superquadric_test_support.h"

namespace isotrace {
namespace {

using superquadric_test::make_superquadric;
using superquadric_test::random_deformations;
using superquadric_test::random_ray;
using superquadric_test::RandomRay;
using superquadric_test::random_deformed_superquadric;
using superquadric_test::sampled_crossings;

// Roots of |(o + t d) / a| = 1 in long double (the ellipsoid as a unit sphere in scaled coordinates).
std::optional<std::array<double, 2>> ellipsoid_roots(const Vec3d& radii, const Vec3d& o, const Vec3d& d) {
    long double a = 0, b = 0, c = -1;
    for (int k = 0; k < 3; ++k) {
        const long double oo = (long double)o[k] / radii[k], dd = (long double)d[k] / radii[k];
        a += dd * dd;
        b += oo * dd;
        c += oo * oo;
    }
    const long double disc = b * b - a * c;
    if (disc < 0) return std::nullopt;
    const long double root = std::sqrt(disc);
    return std::array<double, 2>{double((-b - root) / a), double((-b + root) / a)};
}

void expect_ellipsoid_hits(const Superquadric& s, const Vec3d& radii, const char* what) {
    std::mt19937 random(21);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const RandomRay ray = random_ray(random, radii, i % 4 == 0);
        const auto roots = ellipsoid_roots(radii, ray.origin, ray.direction);
        SuperquadricWork work;
        const auto t = s.first_crossing(ray.origin, ray.direction, 0, 1e30, work);
        if (roots && (*roots)[1] - (*roots)[0] < 1e-6 * std::abs((*roots)[1])) continue;  // grazing: either answer
        std::optional<double> expected;
        if (roots && (*roots)[1] >= 0) expected = (*roots)[0] >= 0 ? (*roots)[0] : (*roots)[1];
        ASSERT_EQ(t.has_value(), expected.has_value()) << what << " ray " << i;
        if (!t) continue;
        ++hits;
        // The chord's conditioning limits any method: the root moves by rounding / |slope|.
        const double chord = (*roots)[1] - (*roots)[0];
        EXPECT_NEAR(*t, *expected, 1e-9 * std::abs(*expected) + 1e-12 * std::abs(*expected) * *expected / chord)
            << what << " ray " << i;
        const Vec3d p = ray.origin + ray.direction * *expected;
        const Vec3d n = normalize(Vec3d(p.x / (radii.x * radii.x), p.y / (radii.y * radii.y), p.z / (radii.z * radii.z)));
        EXPECT_GT(dot(s.normal(ray.origin + ray.direction * *t), n), 1 - 1e-9) << what << " ray " << i;
    }
    EXPECT_GT(hits, 1500) << what;
}

// For ε1 = ε2 = 2/n with n even, F − 1 = Σ ((oₖ + t·dₖ)/aₖ)ⁿ − 1 is a convex polynomial along the ray: its least
// value by bisection on its derivative's sign, and a root on each side by bisection, all in long double.
std::optional<std::array<double, 2>> even_power_roots(const Vec3d& radii, int n, const Vec3d& o, const Vec3d& d) {
    const auto value_and_slope = [&](long double t) {
        long double value = -1, slope = 0;
        for (int k = 0; k < 3; ++k) {
            const long double x = ((long double)o[k] + t * d[k]) / radii[k];
            long double power = 1;  // x^(n − 1)
            for (int i = 1; i < n; ++i) power *= x;
            value += power * x;
            slope += n * power * d[k] / radii[k];
        }
        return std::pair{value, slope};
    };
    // Beyond the box widened by a tenth every coordinate's term alone exceeds 1: the roots lie within.
    long double lo = -1e300, hi = 1e300;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0) continue;
        long double a = (-1.1L * radii[k] - o[k]) / d[k], b = (1.1L * radii[k] - o[k]) / d[k];
        if (a > b) std::swap(a, b);
        lo = std::max(lo, a), hi = std::min(hi, b);
    }
    if (!(lo < hi)) return std::nullopt;
    long double a = lo, b = hi;
    for (int i = 0; i < 200; ++i) {
        const long double m = 0.5L * (a + b);
        (value_and_slope(m).second < 0 ? a : b) = m;
    }
    const long double least = 0.5L * (a + b);
    if (!(value_and_slope(least).first < 0)) return std::nullopt;
    const auto root = [&](long double outside, long double inside) {
        for (int i = 0; i < 200; ++i) {
            const long double m = 0.5L * (outside + inside);
            (value_and_slope(m).first < 0 ? inside : outside) = m;
        }
        return double(0.5L * (outside + inside));
    };
    return std::array<double, 2>{root(lo, least), root(hi, least)};
}

// The even powers are convex shapes and take the convex marches: their crossings are the polynomial's roots, and
// their normals the polynomial's gradient, within the rounding a closed form has.
TEST(SuperquadricIntersection, EvenPowersCrossWhereTheirPolynomialsVanish) {
    const Vec3d radii(0.7, 1.3, 0.9);
    for (const int n : {4, 6, 8, 10}) {
        const Superquadric s = make_superquadric(radii, 2.0 / n, 2.0 / n);
        std::mt19937 random(static_cast<unsigned>(n));
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            const RandomRay ray = random_ray(random, radii, i % 4 == 0);
            const auto roots = even_power_roots(radii, n, ray.origin, ray.direction);
            SuperquadricWork work;
            const auto t = s.first_crossing(ray.origin, ray.direction, 0, 1e30, work);
            if (roots && (*roots)[1] - (*roots)[0] < 1e-6 * std::abs((*roots)[1])) continue;  // grazing: either answer
            std::optional<double> expected;
            if (roots && (*roots)[1] >= 0) expected = (*roots)[0] >= 0 ? (*roots)[0] : (*roots)[1];
            ASSERT_EQ(t.has_value(), expected.has_value()) << "n " << n << " ray " << i;
            if (!t) continue;
            ++hits;
            const double chord = (*roots)[1] - (*roots)[0];
            EXPECT_NEAR(*t, *expected, 1e-9 * std::abs(*expected) + 1e-12 * std::abs(*expected) * *expected / chord)
                << "n " << n << " ray " << i;
            const Vec3d p = ray.origin + ray.direction * *expected;
            Vec3d gradient;
            for (int k = 0; k < 3; ++k) gradient[k] = std::pow(p[k] / radii[k], n - 1) / radii[k];
            EXPECT_GT(dot(s.normal(ray.origin + ray.direction * *t), normalize(gradient)), 1 - 1e-9)
                << "n " << n << " ray " << i;
        }
        EXPECT_GT(hits, 1000) << "n " << n;
    }
}

TEST(SuperquadricIntersection, EpsilonOneIsTheEllipsoid) {
    const Vec3d radii(0.7, 1.3, 2.1);
    expect_ellipsoid_hits(make_superquadric(radii, 1, 1), radii, "closed form");
    // An identity twist sends the same shape through the interval search.
    expect_ellipsoid_hits(make_superquadric(radii, 1, 1, {Twist(0, radii.z)}), radii, "interval search");
    expect_ellipsoid_hits(make_superquadric(radii, 1, 1, {Taper(0, 0, radii.z)}), radii, "identity taper");
}

TEST(SuperquadricIntersection, GrazingRaysHitOnlyWhenTheyCross) {
    // Unit sphere, rays along x at heights 1 - δ (two crossings 2·sqrt(2δ) apart) and 1 + δ (none).
    for (const Superquadric& s : {make_superquadric({1, 1, 1}, 1, 1), make_superquadric({1, 1, 1}, 1, 1, {Twist(0, 1)})}) {
        for (double delta : {1e-3, 1e-6, 1e-9}) {
            SuperquadricWork work;
            const auto inside = s.first_crossing({-3, 0, 1 - delta}, {1, 0, 0}, 0, 10, work);
            ASSERT_TRUE(inside) << delta;
            EXPECT_NEAR(*inside, 3 - std::sqrt(2 * delta - delta * delta), 1e-7);
            EXPECT_FALSE(s.first_crossing({-3, 0, 1 + delta}, {1, 0, 0}, 0, 10, work)) << delta;
        }
    }
}

// The first t ≥ 0 with |x| + |y| + |z| = 1: f is convex and piecewise linear in t, linear between the ray's
// crossings of the coordinate planes, so each piece is solved exactly.
std::optional<double> octahedron_hit(const Vec3d& o, const Vec3d& d) {
    std::vector<double> cuts{0};
    for (int k = 0; k < 3; ++k)
        if (d[k] != 0 && -o[k] / d[k] > 0) cuts.push_back(-o[k] / d[k]);
    std::sort(cuts.begin(), cuts.end());
    cuts.push_back(1e6);
    const auto f = [&](double t) { return std::abs(o.x + t * d.x) + std::abs(o.y + t * d.y) + std::abs(o.z + t * d.z) - 1; };
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double a = cuts[i], b = cuts[i + 1], fa = f(a), fb = f(b);
        if ((fa < 0) != (fb < 0)) return a + (b - a) * fa / (fa - fb);
    }
    return std::nullopt;
}

TEST(SuperquadricIntersection, EpsilonTwoIsTheOctahedron) {
    for (const Superquadric& s : {make_superquadric({1, 1, 1}, 2, 2), make_superquadric({1, 1, 1}, 2, 2, {Twist(0, 1)})}) {
        std::mt19937 random(22);
        int hits = 0;
        for (int i = 0; i < 3000; ++i) {
            const RandomRay ray = random_ray(random, {1, 1, 1}, i % 4 == 0);
            const auto expected = octahedron_hit(ray.origin, ray.direction);
            SuperquadricWork work;
            const auto t = s.first_crossing(ray.origin, ray.direction, 0, 1e30, work);
            // Rays through an edge or vertex within the search resolution may count as grazing.
            const Vec3d p = expected ? ray.origin + ray.direction * *expected : Vec3d();
            const double edge = std::min({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
            if (expected && edge < 1e-6) continue;
            ASSERT_EQ(t.has_value(), expected.has_value()) << i;
            if (!t) continue;
            ++hits;
            EXPECT_NEAR(*t, *expected, 1e-10 * *expected) << i;
            const Vec3d n = s.normal(p);
            EXPECT_NEAR(dot(n, Vec3d(std::copysign(1.0, p.x), std::copysign(1.0, p.y), std::copysign(1.0, p.z))),
                        std::sqrt(3.0), 1e-9);
        }
        EXPECT_GT(hits, 1200);
    }
}

// Slab entry of a box of half-sizes h (or the exit, from inside): t ≥ 0.
std::optional<double> box_hit(const Vec3d& h, const Vec3d& o, const Vec3d& d) {
    double t0 = -1e300, t1 = 1e300;
    for (int k = 0; k < 3; ++k) {
        double a = (-h[k] - o[k]) / d[k], b = (h[k] - o[k]) / d[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    if (t0 > t1 || t1 < 0) return std::nullopt;
    return t0 >= 0 ? t0 : t1;
}

TEST(SuperquadricIntersection, SmallEpsilonApproachesTheBox) {
    // For ε1 = ε2 = ε the surface lies between the box and the box shrunk by 3^(−ε/2) (G ≤ 3^(ε/2)·max|xᵢ/aᵢ|), so
    // every entry is bracketed by the two boxes' entries: 1.1 % of the size at ε = 0.02.
    const double e = 0.02, shrink = std::pow(3.0, -e / 2);
    const Vec3d radii(1, 0.6, 1.4);
    const Superquadric s = make_superquadric(radii, e, e);
    std::mt19937 random(23);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const RandomRay ray = random_ray(random, radii, false);
        const auto outer = box_hit(radii, ray.origin, ray.direction);
        const auto inner = box_hit(radii * shrink, ray.origin, ray.direction);
        SuperquadricWork work;
        const auto t = s.first_crossing(ray.origin, ray.direction, 0, 1e30, work);
        if (inner) {
            ASSERT_TRUE(t) << i;
            EXPECT_GE(*t, *outer * (1 - 1e-12)) << i;
            EXPECT_LE(*t, *inner * (1 + 1e-12)) << i;
            ++hits;
        }
        if (!outer) {
            EXPECT_FALSE(t) << i;
        }
    }
    EXPECT_GT(hits, 1000);
}

TEST(SuperquadricIntersection, EveryHitIsTheFirstSignChangeOnRandomDeformedShapes) {
    std::mt19937 random(24);
    std::uniform_real_distribution<double> exponent(0.1, 4), size(0.4, 1.5);
    int hits = 0;
    for (int shape = 0; shape < 40; ++shape) {
        const Vec3d radii{size(random), size(random), size(random)};
        const Superquadric s = random_deformed_superquadric(random, radii, exponent);
        for (int i = 0; i < 40; ++i) {
            const RandomRay ray = random_ray(random, radii, i % 5 == 0);
            SuperquadricWork work;
            const auto t = s.first_crossing(ray.origin, ray.direction, 0, 20, work);
            const double t_end = t ? *t : 20;
            // No sign change before the hit (beyond the resolution), found by dense sampling.
            const std::vector<double> earlier = sampled_crossings(s, ray.origin, ray.direction, 0, t_end, 4000);
            const double resolution = 1e-6 * t_end;
            for (double c : earlier) EXPECT_GT(c, t_end - resolution - t_end / 4000) << "shape " << shape << " ray " << i;
            if (!t) continue;
            ++hits;
            const Vec3d p = ray.origin + ray.direction * *t;
            // The field changes sign across the hit, and the hit is on the surface.
            EXPECT_NEAR(s.field(p), 0, 1e-9) << "shape " << shape << " ray " << i;
            EXPECT_NE(s.field(ray.origin + ray.direction * (*t * (1 - 1e-9))) < 0,
                      s.field(ray.origin + ray.direction * (*t * (1 + 1e-9))) < 0);
        }
    }
    EXPECT_GT(hits, 500);
}

// Convex superquadrics are answered by Newton marches without a single interval bound, a few point evaluations per
// ray; deformed ones refine their brackets by Newton steps, a handful of evaluations per hit where regula falsi took
// twice as many or more.
TEST(SuperquadricIntersection, RaysCostAFewNewtonSteps) {
    std::mt19937 random(25);
    std::uniform_real_distribution<double> exponent(0.3, 1.8);
    for (const bool deformed : {false, true}) {
        SuperquadricWork work;
        int rays = 0;
        for (int shape = 0; shape < 20; ++shape) {
            const Vec3d radii{1, 0.8, 1.2};
            const Superquadric s = deformed ? random_deformed_superquadric(random, radii, exponent)
                                            : make_superquadric(radii, exponent(random), exponent(random));
            for (int i = 0; i < 50; ++i, ++rays) {
                const RandomRay ray = random_ray(random, radii, false);
                s.first_crossing(ray.origin, ray.direction, 0, 20, work);
            }
        }
        ASSERT_GT(work.search.crossings, 200u);
        if (!deformed) {
            const double per_ray = double(work.search.evaluations) / rays;
            std::printf("convex: %.2f evaluations per ray, %llu interval bounds\n", per_ray,
                        (unsigned long long)(work.search.interval_bounds + work.search.slope_bounds));
            EXPECT_EQ(work.search.interval_bounds + work.search.slope_bounds, 0u);
            EXPECT_LT(per_ray, 8.0);
            continue;
        }
        const double per_hit = double(work.search.evaluations - work.search.halvings) / double(work.search.crossings);
        std::printf("deformed: %.2f refinement evaluations per hit\n", per_hit);
        EXPECT_LT(per_hit, 6.0);
    }
}

// A ray through the empty corner of a star's box (both exponents above 2) or of a mixed shape's is passed over
// without a point evaluation: the gauge's least value over the stretch exceeds 1.
TEST(SuperquadricIntersection, StretchesOutsideTheGaugesUnitBallAreNotSearched) {
    for (const auto& [north_south, east_west] : {std::pair{3.5, 3.5}, std::pair{0.3, 3.5}, std::pair{3.5, 0.3}}) {
        const Superquadric s = make_superquadric({1, 1, 1}, north_south, east_west);
        SuperquadricWork work;
        // Along the box's edge x = y = 0.95, outside the surface, through the plane z = 0.
        EXPECT_FALSE(s.first_crossing({0.95, 0.95, -2}, {0, 0, 1}, 0, 10, work));
        EXPECT_FALSE(s.blocks({0.95, 0.95, -2}, {0, 0, 1}, 0, 10, work));
        EXPECT_EQ(work.point_values, 0u);
        // Through the middle it is searched, and hits.
        EXPECT_TRUE(s.first_crossing({0.01, 0.02, -2}, {0, 0, 1}, 0, 10, work));
        EXPECT_GT(work.point_values, 0u);
    }
}

// A ray diagonally through a deformed shape's box at height z, passing the z axis at `offset` times `radius` (the
// bound's radius there): beside the bound it is settled before the shell's walk, without a bound of g or a point
// value; through the axis it is searched.
void expect_settled_beside(const Superquadric& s, double radius, double z, double offset) {
    const Vec3d across = normalize(Vec3d{1, -1, 0}), out = normalize(Vec3d{1, 1, 0});
    SuperquadricWork work;
    const Vec3d beside = out * (radius * offset) - across * 3.0 + Vec3d{0, 0, z};
    EXPECT_FALSE(s.first_crossing(beside, across, 0, 10, work));
    EXPECT_FALSE(s.blocks(beside, across, 0, 10, work));
    EXPECT_EQ(work.search.interval_bounds, 0u);
    EXPECT_EQ(work.point_values, 0u);
    s.first_crossing(Vec3d{0, 0, z} - across * 3.0, across, 0, 10, work);
    EXPECT_GT(work.search.interval_bounds + work.point_values, 0u);
}

// The round cylinder's radius around a superellipsoid of radii 0.4: 0.4 for round and star-shaped cross-sections,
// more for squarish ones.
double round_cylinder_radius(double east_west) { return 0.4 * std::max(1.0, std::exp2((1 - east_west) / 2)); }

// A twist turns every cross-section about z, so the round quadrics around the undeformed solid hold the twisted one.
TEST(SuperquadricIntersection, ARayBesideATwistedSolidsRoundQuadricsIsNotSearched) {
    for (const auto& [e1, e2] : {std::pair{1.0, 1.0}, {0.3, 1.0}, {2.5, 2.5}, {0.3, 0.3}}) {
        SCOPED_TRACE(testing::Message() << e1 << " " << e2);
        const Superquadric s = make_superquadric({0.4, 0.4, 0.4}, e1, e2, {Twist(3.14159 / 0.8, 0.4)});
        expect_settled_beside(s, round_cylinder_radius(e2), 0.05, 1.001);
    }
}

// A taper widens the cylinder around the undeformed solid into a cone about z that holds the tapered one: here a ray
// passes beside it through the box's narrow end.
TEST(SuperquadricIntersection, ARayBesideATaperedSolidsConeIsNotSearched) {
    for (const auto& [e1, e2] : {std::pair{1.0, 1.0}, {0.3, 1.0}, {2.5, 2.5}, {0.3, 0.3}}) {
        SCOPED_TRACE(testing::Message() << e1 << " " << e2);
        // Full size at the bottom (z = −0.4), 0.4 of it at the top; at z = 0.32, 1 − 0.6 · 0.9 of it.
        const Superquadric s = make_superquadric({0.4, 0.4, 0.4}, e1, e2, {Taper(-0.6, -0.6, 0.4)});
        expect_settled_beside(s, round_cylinder_radius(e2) * (1 - 0.6 * 0.9), 0.32, 1.01);
    }
}

// A bend turns each cross-section about its centre, so the bent solid lies in an annular sector about it: a ray through
// the box on the centre's side of the arc, inside the sector's hole and close to the surface, is settled before the
// shell's walk.
TEST(SuperquadricIntersection, ARayThroughABentSolidsHoleIsNotSearched) {
    for (const auto& [e1, e2] : {std::pair{1.0, 1.0}, {0.3, 1.0}, {1.0, 0.3}}) {
        SCOPED_TRACE(testing::Message() << e1 << " " << e2);
        // Radius 1/1.2 about (1/1.2, ·, 0): at z = 0 the solid reaches x = 0.4, at its ends x ≈ 0.45.
        const Superquadric s = make_superquadric({0.4, 0.4, 0.4}, e1, e2, {Bend(1.2, 0, 0, {-0.4, 0.4})});
        ASSERT_TRUE(s.deformation().deformed_box().contains({0.405, 0, 0}));
        SuperquadricWork work;
        EXPECT_FALSE(s.first_crossing({0.405, -3, 0}, {0, 1, 0}, 0, 10, work));
        EXPECT_FALSE(s.blocks({0.405, -3, 0}, {0, 1, 0}, 0, 10, work));
        EXPECT_EQ(work.search.interval_bounds, 0u);
        EXPECT_EQ(work.point_values, 0u);
        EXPECT_TRUE(s.first_crossing({0.1, -3, 0}, {0, 1, 0}, 0, 10, work));
    }
}

// Occlusion settled by an unrefined bracket gives first_crossing's answer on every ray, ranges cut short included,
// for less work.
TEST(SuperquadricIntersection, BlocksAgreesWithTheFirstCrossingForLessWork) {
    std::mt19937 random(26);
    std::uniform_real_distribution<double> exponent(0.1, 4), size(0.4, 1.5), range(0, 12);
    SuperquadricWork by_blocks, by_crossing;
    int blocked = 0;
    for (int shape = 0; shape < 40; ++shape) {
        const Vec3d radii{size(random), size(random), size(random)};
        const Superquadric s = shape % 2 ? random_deformed_superquadric(random, radii, exponent)
                                         : make_superquadric(radii, exponent(random), exponent(random));
        for (int i = 0; i < 50; ++i) {
            const RandomRay ray = random_ray(random, radii, i % 5 == 0);
            const float t_max = float(range(random));
            const std::optional<double> t = s.first_crossing(ray.origin, ray.direction, 0, t_max, by_crossing);
            const bool expected = t && *t > 0 && float(*t) < t_max;
            EXPECT_EQ(s.blocks(ray.origin, ray.direction, 0, t_max, by_blocks), expected) << shape << " " << i;
            blocked += expected;
        }
    }
    EXPECT_GT(blocked, 300);
    EXPECT_LT(by_blocks.point_values, by_crossing.point_values);
    std::printf("point values: %llu blocking, %llu locating\n", (unsigned long long)by_blocks.point_values,
                (unsigned long long)by_crossing.point_values);
}

// Occlusion queries along +x from `origin` through a shape with radii `radii` and each pair of exponents: blocked
// within 10 after exactly `values` point values, and not blocked when the range stops short of the solid, at
// `short_of`.
void expect_blocked_along_x(const Vec3d& radii, std::initializer_list<std::pair<double, double>> exponents,
                            const Vec3d& origin, std::uint64_t values, float short_of) {
    for (const auto& [e1, e2] : exponents) {
        const Superquadric s = make_superquadric(radii, e1, e2);
        SuperquadricWork work;
        EXPECT_TRUE(s.blocks(origin, {1, 0, 0}, 0, 10, work)) << e1 << " " << e2;
        EXPECT_EQ(work.point_values, values) << e1 << " " << e2;
        EXPECT_FALSE(s.blocks(origin, {1, 0, 0}, 0, short_of, work)) << e1 << " " << e2;
    }
}

// An undeformed shape's occlusion query that enters the quadrics around it from outside and reaches the ellipsoid
// inside it is settled by the two alone, without a point value; one that stops short of the surface is not blocked.
TEST(SuperquadricIntersection, ARayThroughAShapesInscribedEllipsoidIsBlockedWithoutAPointValue) {
    expect_blocked_along_x(
        {0.5, 0.8, 1.2},
        {{0.1, 1.0}, {0.5, 0.3}, {1.0, 2.0}, {2.0, 2.0}, {0.02, 0.02}, {3.0, 3.0}, {0.5, 3.0}, {4.0, 1.0}},
        {-3, 0.05, 0.1}, 0, 2.4f);
}

// One that passes beside that ellipsoid through a convex solid (a box's edge) is settled by one point value where it
// comes nearest the centre; one that stops short of the solid is not blocked.
TEST(SuperquadricIntersection, ARayThroughAConvexSolidBesideItsEllipsoidIsBlockedByOnePointValue) {
    expect_blocked_along_x({1, 1, 1}, {{0.1, 0.1}, {0.3, 0.05}, {0.05, 1.0}}, {-3, 0.75, 0.75}, 1, 1.5f);
}

// One through a pinched shape beside that ellipsoid (its bulk about the plane z = 0) is settled by the values where it
// crosses the coordinate planes, without bounding g: the ray below crosses the solid about the plane x = 0.
TEST(SuperquadricIntersection, ARayThroughAPinchedSolidBesideItsEllipsoidIsBlockedByItsCutsValues) {
    const Superquadric s = make_superquadric({1, 1, 1}, 3.5, 0.3);
    SuperquadricWork work;
    EXPECT_TRUE(s.blocks({-3, 0.36, -0.11}, {1, -0.127, 0.26}, 0, 10, work));
    EXPECT_EQ(work.search.interval_bounds, 0u);
    EXPECT_LE(work.point_values, 2u);
}

// A deformed shape's occlusion query from outside through the solid is settled by the shell alone (the cell where
// the middle of its stretch lies, or a run of surface cells between cells without surface outside and inside it),
// or by one point value at that middle, whatever the exponents, without bounding g anywhere; one that stops short
// of the surface is not blocked.
TEST(SuperquadricIntersection, ARayThroughADeformedSolidIsBlockedByTheShellOrOnePointValue) {
    for (const auto& [e1, e2] : {std::pair{1.0, 1.0}, {0.3, 0.3}, {2.5, 2.5}, {0.3, 2.5}, {0.05, 1.0}, {4.0, 4.0}}) {
        for (const Deformation& stage : {Deformation(Twist(3.14159 / 0.8, 0.4)), Deformation(Taper(0.5, -0.3, 0.4)),
                                         Deformation(Bend(0.8, 0.3, 0.0, {-0.4, 0.4}))}) {
            const Superquadric s = make_superquadric({0.4, 0.4, 0.4}, e1, e2, {stage});
            SuperquadricWork work;
            EXPECT_TRUE(s.blocks({-3, 0.02, 0.03}, {1, 0, 0}, 0, 10, work)) << e1 << " " << e2;
            EXPECT_LE(work.point_values, 1u) << e1 << " " << e2;
            EXPECT_EQ(work.search.interval_bounds, 0u) << e1 << " " << e2;
            EXPECT_FALSE(s.blocks({-3, 0.02, 0.03}, {1, 0, 0}, 0, 2.4f, work)) << e1 << " " << e2;
        }
    }
}

// A ray leaving a convex shape's surface is settled by one point value, also an even-exponent shape's.
TEST(SuperquadricIntersection, ARayLeavingAConvexSurfaceTakesOnePointValue) {
    for (const auto& [e1, e2] : {std::pair{0.5, 0.5}, {0.1, 1.0}, {1.0, 2.0}, {0.3, 0.7}}) {
        const Superquadric s = make_superquadric({0.5, 0.8, 1.2}, e1, e2);
        for (const auto& [eta, omega] : {std::pair{0.3, 0.4}, {-1.0, 2.5}, {0.0, -2.0}}) {
            const Vec3d p = s.surface_point(eta, omega);
            const Vec3d n = s.normal(p);
            SuperquadricWork work;
            EXPECT_FALSE(s.first_crossing(p + n * 1e-4, n, 0, 10, work)) << e1 << " " << e2 << " " << eta;
            EXPECT_EQ(work.point_values, 1u) << e1 << " " << e2 << " " << eta;
        }
    }
}

// Rays that start just off the surface and leave it, as shadow rays do, many of them nearly along it (those meet the
// shape again soon, within the stretch the search starts with): occlusion gives first_crossing's answer.
TEST(SuperquadricIntersection, BlocksAgreesWithTheFirstCrossingOnRaysLeavingTheSurface) {
    std::mt19937 random(27);
    std::uniform_real_distribution<double> exponent(0.1, 4), size(0.4, 1.5), unit(-1, 1), angle(-3.1, 3.1);
    SuperquadricWork work;
    int blocked = 0;
    for (int shape = 0; shape < 30; ++shape) {
        const Vec3d radii{size(random), size(random), size(random)};
        const Superquadric s = random_deformed_superquadric(random, radii, exponent);
        for (int i = 0; i < 60; ++i) {
            const Vec3d p = s.surface_point(0.5 * angle(random), angle(random));
            const Vec3d n = s.normal(p);
            if (!is_finite(n)) continue;
            const Vec3d across = normalize(cross(n, Vec3d{unit(random), unit(random), unit(random)}));
            const double lift = i % 2 ? 0.02 : 0.5 + 0.5 * unit(random);  // nearly along the surface, or not
            const Vec3d direction = normalize(across + n * lift);
            const Vec3d origin = p + n * (1e-4 * std::min({radii.x, radii.y, radii.z}));
            const float t_max = float(4 * std::max({radii.x, radii.y, radii.z}));
            const std::optional<double> t = s.first_crossing(origin, direction, 0, t_max, work);
            const bool expected = t && *t > 0 && float(*t) < t_max;
            EXPECT_EQ(s.blocks(origin, direction, 0, t_max, work), expected) << shape << " " << i;
            blocked += expected;
        }
    }
    EXPECT_GT(blocked, 50);
}

TEST(SuperquadricIntersection, PlacementIsAppliedAndTIsPreserved) {
    const Transform placement = Transform::translate({1, -2, 0.5}) * Transform::rotate({1, 2, 3}, 40) *
                                Transform::scale({1.5, 1.5, 1.5});
    const Vec3d radii(0.5, 0.7, 1.1);
    const Superquadric local = make_superquadric(radii, 0.6, 1.7, {Taper(0.3, 0.2, radii.z), Twist(0.8, radii.z)});
    const Superquadric placed = make_superquadric(radii, 0.6, 1.7, {Taper(0.3, 0.2, radii.z), Twist(0.8, radii.z)}, placement);
    std::mt19937 random(25);
    for (int i = 0; i < 300; ++i) {
        const RandomRay ray = random_ray(random, radii, i % 3 == 0);
        SuperquadricWork work;
        const auto a = local.first_crossing(ray.origin, ray.direction, 0, 100, work);
        const auto b = placed.first_crossing(placement.point(ray.origin), placement.vector(ray.direction), 0, 100, work);
        ASSERT_EQ(a.has_value(), b.has_value()) << i;
        if (!a) continue;
        EXPECT_NEAR(*a, *b, 1e-9 * *a);
        const Vec3d n_local = local.normal(ray.origin + ray.direction * *a);
        const Vec3d n_placed = placed.normal(placement.point(ray.origin + ray.direction * *a));
        EXPECT_GT(dot(normalize(placement.normal(n_local)), n_placed), 1 - 1e-9);
    }
}

TEST(SuperquadricIntersection, TwistLeavesTheAxisRayUnchanged) {
    const Vec3d radii(0.6, 0.9, 1.2);
    for (double e1 : {0.3, 1.0, 2.5})
        for (double e2 : {0.3, 1.0, 2.5}) {
            const Superquadric plain = make_superquadric(radii, e1, e2);
            const Superquadric twisted = make_superquadric(radii, e1, e2, {Twist(2.5, radii.z)});
            for (const Vec3d& d : {Vec3d(0, 0, -1), Vec3d(0, 0, 1)}) {
                SuperquadricWork work;
                const Vec3d o = d * -5.0;
                const auto a = plain.first_crossing(o, d, 0, 10, work), b = twisted.first_crossing(o, d, 0, 10, work);
                ASSERT_TRUE(a && b);
                EXPECT_NEAR(*a, 5 - radii.z, 1e-12);
                EXPECT_NEAR(*b, *a, 1e-12);
            }
        }
}

TEST(SuperquadricIntersection, IdentityDeformationsEqualTheUndeformedShape) {
    std::mt19937 random(26);
    const Vec3d radii(0.8, 0.5, 1.1);
    for (double e : {0.3, 0.5, 1.3, 3.0}) {
        const Superquadric plain = make_superquadric(radii, e, 0.8);
        const Superquadric identity =
            make_superquadric(radii, e, 0.8, {Taper(0, 0, radii.z), Twist(0, radii.z), Bend(1e-12, 0.4, 0, {-1.1, 1.1})});
        for (int i = 0; i < 500; ++i) {
            const RandomRay ray = random_ray(random, radii, i % 4 == 0);
            SuperquadricWork work;
            const auto a = plain.first_crossing(ray.origin, ray.direction, 0, 100, work);
            const auto b = identity.first_crossing(ray.origin, ray.direction, 0, 100, work);
            if (a.has_value() != b.has_value()) {
                // Only a ray grazing within the resolution may differ.
                const double t = a ? *a : *b;
                EXPECT_LT(std::abs(plain.field(ray.origin + ray.direction * t)), 1e-6) << i;
                continue;
            }
            if (!a) continue;
            EXPECT_NEAR(*a, *b, 1e-9 * *a) << "e " << e << " ray " << i;
            const Vec3d p = ray.origin + ray.direction * *a;
            EXPECT_GT(dot(plain.normal(p), identity.normal(p)), 1 - 1e-6) << "e " << e << " ray " << i;
        }
    }
}

TEST(SuperquadricIntersection, NormalsMatchFiniteDifferencesOfTheDeformedField) {
    std::mt19937 random(27);
    std::uniform_real_distribution<double> exponent(0.3, 1.8), eta(-1.3, 1.3), omega(-3.1, 3.1);
    int checked = 0;
    for (int shape = 0; shape < 30; ++shape) {
        const Vec3d radii(0.9, 0.6, 1.2);
        const Superquadric s = random_deformed_superquadric(random, radii, exponent);
        for (int i = 0; i < 30; ++i) {
            const double e = eta(random), w = omega(random);
            const Vec3d undeformed = s.shape().surface_point(e, w);
            if (std::min({std::abs(undeformed.x), std::abs(undeformed.y), std::abs(undeformed.z)}) < 0.05) continue;
            const Vec3d p = s.surface_point(e, w);
            Vec3d gradient;
            const double h = 1e-6;
            for (int k = 0; k < 3; ++k) {
                Vec3d a = p, b = p;
                a[k] -= h;
                b[k] += h;
                gradient[k] = (s.field(b) - s.field(a)) / (2 * h);
            }
            EXPECT_GT(dot(s.normal(p), normalize(gradient)), 1 - 1e-5) << shape << " " << i;
            ++checked;
        }
    }
    EXPECT_GT(checked, 400);
}

TEST(SuperquadricBounds, ContainSampledSurfacePointsOfRandomDeformations) {
    std::mt19937 random(28);
    std::uniform_real_distribution<double> exponent(0.02, 4), size(0.3, 2), eta(-1.5707963, 1.5707963),
        omega(-3.14159265, 3.14159265);
    for (int shape = 0; shape < 100; ++shape) {
        const Vec3d radii{size(random), size(random), size(random)};
        const Transform placement = Transform::translate({size(random), -size(random), 0}) * Transform::rotate({1, 1, 0}, 30);
        const Superquadric s = random_deformed_superquadric(random, radii, exponent, placement);
        const IntervalBox bounds = s.bounds();
        Vec3d lowest = bounds.upper(), highest = bounds.lower();
        for (int i = 0; i < 2000; ++i) {
            const double e = eta(random), w = omega(random);
            const Vec3d p = s.surface_point(e, w);
            ASSERT_TRUE(bounds.contains(p)) << shape << " " << i;
            lowest = min(lowest, p);
            highest = max(highest, p);
        }
        // And they are reasonably tight: within the object's size of the sampled extent on every side.
        const double size_of = length(highest - lowest);
        for (int k = 0; k < 3; ++k) {
            EXPECT_LT(lowest[k] - bounds[k].lo, size_of) << shape;
            EXPECT_LT(bounds[k].hi - highest[k], size_of) << shape;
        }
    }
}

// The shell's cell bounds of random deformed shapes over small random boxes: every point's field lies in the range
// they give over the point itself (value at the centre plus the gradient's bounds times the offset), and the
// difference quotient of the field along a random line through the box lies in their slope along it.
TEST(SuperquadricBounds, CellBoundsHoldTheFieldAndItsSlopesOverTheCell) {
    std::mt19937 random(30);
    std::uniform_real_distribution<double> exponent(0.02, 4), unit(-1, 1), fraction(0, 1), side(0.005, 0.1);
    constexpr auto kBeyond = DeformationChain::BeyondUndeformedBox::Gauge;
    int known = 0;
    for (int shape = 0; shape < 60; ++shape) {
        const Vec3d radii{0.5 + fraction(random), 0.5 + fraction(random), 0.5 + fraction(random)};
        const Superquadric s = random_deformed_superquadric(random, radii, exponent);
        const IntervalBox box = s.deformation().deformed_box();
        for (int cell = 0; cell < 200; ++cell) {
            const Vec3d centre{box.x.lo + box.x.width() * fraction(random), box.y.lo + box.y.width() * fraction(random),
                               box.z.lo + box.z.width() * fraction(random)};
            const Vec3d half = Vec3d{side(random), side(random), side(random)} * 0.5;
            const IntervalBox around{{centre.x - half.x, centre.x + half.x}, {centre.y - half.y, centre.y + half.y},
                                     {centre.z - half.z, centre.z + half.z}};
            const ShellCellBounds bounds = s.cell_bounds(around, centre);
            if (!bounds.known) continue;
            ++known;
            EXPECT_EQ(bounds.value, s.local_field(centre, kBeyond));
            // The bounds hold over the cell's part within the deformed box, where the search asks.
            IntervalBox within = around;
            ASSERT_TRUE(clip_box(within, box));
            for (int i = 0; i < 20; ++i) {
                Vec3d p;
                for (int k = 0; k < 3; ++k) p[k] = within[k].lo + within[k].width() * fraction(random);
                EXPECT_TRUE(bounds.range(p, p).contains(s.local_field(p, kBeyond))) << shape << " " << cell;
                // A line through p within that part: its difference quotient is g′ somewhere between (mean value).
                const Vec3d d = normalize(Vec3d{unit(random), unit(random), unit(random)});
                double reach = 1e300;
                for (int k = 0; k < 3; ++k)
                    if (d[k] != 0) reach = std::min(reach, ((d[k] > 0 ? within[k].hi : within[k].lo) - p[k]) / d[k]);
                const double h = 0.5 * reach;
                if (!(h > 1e-6)) continue;
                const double quotient = (s.local_field(p + d * h, kBeyond) - s.local_field(p, kBeyond)) / h;
                const Interval slope = bounds.slope(d);
                EXPECT_GE(quotient, slope.lo - 1e-9) << shape << " " << cell;
                EXPECT_LE(quotient, slope.hi + 1e-9) << shape << " " << cell;
            }
        }
    }
    EXPECT_GT(known, 3000);
}

// The outer cells of the shell reach past the deformed box's faces; the search asks nothing there, so their bounds
// are taken over their part within the box. A twisted boxy shape's flat cap lies in the top layer of cells, which
// keep their gradient bounds.
TEST(SuperquadricBounds, CellsAtTheDeformedBoxFacesKeepTheirBounds) {
    const Superquadric s = make_superquadric({0.4, 0.4, 0.4}, 0.3, 0.3, {Twist(3.14159 / 0.8, 0.4)});
    const IntervalBox& box = s.deformation().deformed_box();
    const double side = box.z.width() / 32;
    int known = 0;
    for (int i = 0; i < 8; ++i) {
        const double x = -0.2 + 0.05 * i;
        const IntervalBox cell{{x, x + side}, {-side / 2, side / 2}, {box.z.hi - side, box.z.hi + 1e-6 * side}};
        const Vec3d centre = (cell.lower() + cell.upper()) * 0.5;
        ASSERT_FALSE(s.local_field_range(cell).excludes_zero()) << x;  // the cap crosses the cell
        known += s.cell_bounds(cell, centre).known;
    }
    EXPECT_EQ(known, 8);
}

TEST(SuperquadricIntersection, FarAwayRaysAndRaysAlongThePlanesStayFinite) {
    for (double e : {0.02, 1.0, 2.0, 4.0}) {
        const Superquadric s = make_superquadric({1, 1, 1}, e, e);
        SuperquadricWork work;
        const auto far = s.first_crossing({0, 0, 1e15}, {0, 0, -1}, 0, 1e30, work);
        ASSERT_TRUE(far) << e;
        EXPECT_NEAR(*far, 1e15 - 1, 1);
        const auto along_plane = s.first_crossing({-5, 0, 0}, {1, 0, 0}, 0, 100, work);
        ASSERT_TRUE(along_plane) << e;
        EXPECT_NEAR(*along_plane, 4, 1e-12);
        EXPECT_TRUE(is_finite(s.normal({1, 0, 0})));
    }
}

TEST(Superquadric, CertainlyOutsideHoldsOnlyForPointsTheSolidCannotReach) {
    // An ellipsoid of radius 1, then scaled by 2: its gauge at (1.5, 0, 0) is 1.5, and a step v moves it by at
    // most √3·|v| (divided by the placement's scale).
    const Superquadric ball = make_superquadric({1, 1, 1}, 1, 1);
    EXPECT_TRUE(ball.certainly_outside({1.5, 0, 0}, 0.28));
    EXPECT_FALSE(ball.certainly_outside({1.5, 0, 0}, 0.3));
    const Superquadric scaled = make_superquadric({1, 1, 1}, 1, 1, {}, Transform::scale({2, 2, 2}));
    EXPECT_TRUE(scaled.certainly_outside({3, 0, 0}, 0.57));
    EXPECT_FALSE(scaled.certainly_outside({3, 0, 0}, 0.58));
    // Undecided where the gauge is no norm: exponents above 2, or a deformation.
    EXPECT_FALSE(make_superquadric({1, 1, 1}, 3, 1).certainly_outside({5, 0, 0}, 0.1));
    std::mt19937 random(5);
    EXPECT_FALSE(make_superquadric({1, 1, 1}, 1, 1, random_deformations(random, {1, 1, 1})).certainly_outside({5, 0, 0}, 0.1));

    // Random convex shapes and placements: no point within the distance of a point it calls outside is inside.
    std::uniform_real_distribution<double> exponent(0.02, 2), size(0.3, 2), unit(-1, 1), fraction(0, 1);
    int decided = 0;
    for (int shape = 0; shape < 200; ++shape) {
        const Vec3d radii(size(random), size(random), size(random));
        const Transform placement = Transform::translate({unit(random), unit(random), unit(random)}) *
                                    Transform::rotate({unit(random), unit(random), 1}, 180 * unit(random)) *
                                    Transform::scale(Vec3d(1, 1, 1) * size(random));
        const Superquadric s = make_superquadric(radii, exponent(random), exponent(random), {}, placement);
        for (int point = 0; point < 50; ++point) {
            const Vec3d p = placement.point(Vec3d(unit(random), unit(random), unit(random)) * 2.5 * max_component(radii));
            const double distance = fraction(random) * max_component(radii);
            if (!s.certainly_outside(p, distance)) continue;
            ++decided;
            for (int step = 0; step < 200; ++step) {
                const Vec3d v = normalize(Vec3d(unit(random), unit(random), unit(random))) * distance *
                                std::cbrt(step % 4 == 0 ? 1 : fraction(random));
                ASSERT_GT(s.field(p + v), 0) << "shape " << shape << " point " << point;
            }
        }
    }
    EXPECT_GT(decided, 1000);
}

// contains() skips the gauge outside the deformed box and agrees with the field's sign everywhere: random shapes,
// deformed or not, in every exponent range, at points inside, near and beyond their boxes (and on the boxes' faces).
TEST(Superquadric, ContainsIsTheFieldsSign) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> exponent(0.02, 4), size(0.3, 2), unit(-1, 1);
    int inside = 0, outside_box = 0;
    for (int shape = 0; shape < 200; ++shape) {
        const Vec3d radii(size(random), size(random), size(random));
        const Transform placement = Transform::translate({unit(random), unit(random), unit(random)}) *
                                    Transform::rotate({unit(random), unit(random), 1}, 180 * unit(random));
        const Superquadric s = shape % 2 ? random_deformed_superquadric(random, radii, exponent, placement)
                                         : make_superquadric(radii, exponent(random), exponent(random), {}, placement);
        const IntervalBox& box = s.deformation().deformed_box();
        for (int point = 0; point < 200; ++point) {
            Vec3d local = Vec3d(unit(random), unit(random), unit(random)) * 1.5 * max_component(radii);
            if (point % 10 == 0) local.x = unit(random) < 0 ? box.x.lo : box.x.hi;
            const Vec3d p = placement.point(local);
            ASSERT_EQ(s.contains(p), s.field(p) < 0) << "shape " << shape << " point " << point;
            inside += s.contains(p);
            outside_box += !box.contains(placement.inverse_point(p));
        }
    }
    EXPECT_GT(inside, 500);
    EXPECT_GT(outside_box, 10000);
}

}  // namespace
}  // namespace isotrace
