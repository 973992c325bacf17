// The bounds of g and g′ along a ray through random deformed superquadrics: the slope bound contains the
// derivative (finite differences), a stretch it proves monotone holds exactly one crossing when its ends differ
// in sign and none otherwise (dense sampling), and the search that uses it finds the same crossings as the
// search without it; the bounds hold sampled values and slopes, also on stretches that reach beyond the undeformed
// box.
#include "geometry/superquadric/superquadric_along_ray.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "geometry/superquadric/superquadric_test_support.h"
#include "renderer/math/line_box_clip.h"

namespace isotrace {
namespace {

using superquadric_test::make_superquadric;
using superquadric_test::random_deformed_superquadric;

struct RandomCase {
    Superquadric superquadric;
    Vec3d origin, direction;
};

// A random deformed superquadric (exponents 0.1 to 4: convex, and pinched beyond 2) and a ray from a shell
// around it toward a point near it.
RandomCase random_case(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(-1, 1), exponent(0.1, 4), size(0.4, 1.5);
    const Vec3d radii{size(random), size(random), size(random)};
    Superquadric s = random_deformed_superquadric(random, radii, exponent);
    const Vec3d target{unit(random) * radii.x, unit(random) * radii.y, unit(random) * radii.z};
    const Vec3d origin = normalize(Vec3d{unit(random), unit(random), unit(random)}) * 5.0;
    return {std::move(s), origin, (target - origin) * (0.5 + std::abs(unit(random)))};
}

// The stretch of the ray inside the deformed box (where the search runs), or nothing.
std::optional<LineBoxClip> box_stretch(const Superquadric& s, const SuperquadricAlongRay& ray) {
    const IntervalBox& box = s.deformation().deformed_box();
    return clip_line_to_box(box.lower(), box.upper(), ray.local_origin(), ray.local_direction(), 0, 1e30);
}

// Calls visit(superquadric, ray, a, b) for stretches [a, b] of rays through random deformed superquadrics: per ray, 20 at
// random places of its stretch in the deformed box (widths 1 to 10⁻⁴ of it) and 4 starting just before each
// crossing the search finds.
template <class Visit>
void for_random_stretches(unsigned seed, int cases, Visit&& visit) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(0, 1);
    for (int i = 0; i < cases; ++i) {
        const RandomCase c = random_case(random);
        const SuperquadricAlongRay ray(c.superquadric, c.origin, c.direction);
        const auto stretch = box_stretch(c.superquadric, ray);
        if (!stretch) continue;
        const double length = stretch->t_exit - stretch->t_enter;
        std::vector<Crossing> found;
        SuperquadricWork work;
        c.superquadric.crossings(c.origin, c.direction, 0, 1e30, found, work);
        for (int j = 0; j < 20 + 4 * int(found.size()); ++j) {
            const double width = length * std::pow(10.0, -4 * uniform(random));
            const double a = j < 20 ? stretch->t_enter + (length - width) * uniform(random)
                                    : found[(j - 20) / 4].t - width * uniform(random);
            visit(c.superquadric, ray, a, a + width);
        }
    }
}

TEST(SuperquadricAlongRay, TheSlopeBoundContainsTheDerivative) {
    int checked = 0;
    for_random_stretches(91, 300, [&](const Superquadric&, const SuperquadricAlongRay& ray, double a, double b) {
        const Interval slope = ray.slope_bound(a, b);
        if (!slope.is_finite()) return;
        for (int k = 1; k < 8; ++k) {
            const double t = a + (b - a) * k / 8, h = 1e-6 * (b - a);
            const double derivative = (ray.value(t + h) - ray.value(t - h)) / (2 * h);
            // The differences' truncation, and the rounding of g (a few ulps of values near 0 to 1) over 2h.
            const double tolerance = 1e-5 * (std::abs(slope.lo) + std::abs(slope.hi)) + 1e-9 + 1e-15 / h;
            EXPECT_GE(derivative, slope.lo - tolerance) << "[" << a << ", " << b << "] t " << t;
            EXPECT_LE(derivative, slope.hi + tolerance) << "[" << a << ", " << b << "] t " << t;
            ++checked;
        }
    });
    EXPECT_GT(checked, 5000);
}

// Where the bound of g′ is finite (the stretch lies inside every stage box, where g is continuous): g at 200 points
// of [a, b] (its ends included) within the bound of g, and g′ there (the point derivative through the chain's
// Jacobians, checked against differences by InverseAlongCarriesVelocitiesBack) within the bound of g′; returns the
// number of points checked.
int check_bounds_hold_samples(const SuperquadricAlongRay& ray, double a, double b) {
    const Interval value = ray.bound(a, b), slope = ray.slope_bound(a, b);
    if (!slope.is_finite()) return 0;
    int checked = 0;
    for (int k = 0; k <= 200; ++k) {
        const double t = k == 200 ? b : a + (b - a) * k / 200;
        const double g = ray.value(t);
        EXPECT_TRUE(value.contains(g)) << "[" << a << ", " << b << "] t " << t << " g " << g << " not in [" << value.lo
                                       << ", " << value.hi << "]";
        const double derivative = ray.value_and_slope(t).derivative;
        if (std::isnan(derivative)) continue;
        EXPECT_TRUE(slope.contains(derivative)) << "[" << a << ", " << b << "] t " << t << " g′ " << derivative
                                                << " not in [" << slope.lo << ", " << slope.hi << "]";
        ++checked;
    }
    return checked;
}

TEST(SuperquadricAlongRay, TheBoundsHoldSampledValuesAndSlopes) {
    int checked = 0;
    for_random_stretches(94, 300, [&](const Superquadric&, const SuperquadricAlongRay& ray, double a, double b) {
        checked += check_bounds_hold_samples(ray, a, b);
    });
    EXPECT_GT(checked, 100000);
}

// Near the flat faces of a twisted rounded box the surface lies just inside the undeformed box, and stretches there
// reach past its faces; the field continues there by the gauge (continuous, above 0), so such a stretch still has a
// bound of g′, which holds the slopes, and the search settles it with few halvings.
TEST(SuperquadricAlongRay, StretchesBeyondTheUndeformedBoxKeepTheirSlopeBound) {
    const Superquadric s = make_superquadric({0.5, 0.5, 1}, 0.1, 0.1, {Twist(1.2, 1)});
    const Vec3d& undeformed = s.deformation().undeformed_box().upper();
    // Along the x face (the twist turns it by 0.6 at z = −0.5), starting inside the deformed box but outside the
    // undeformed one.
    const Vec3d origin{1.1 * undeformed.x, -0.9, -0.5}, direction{0, 1, 0.02};
    const SuperquadricAlongRay ray(s, origin, direction);
    const auto stretch = box_stretch(s, ray);
    ASSERT_TRUE(stretch);
    int beyond = 0, checked = 0;
    const double length = stretch->t_exit - stretch->t_enter;
    for (int j = 0; j < 64; ++j) {
        const double a = stretch->t_enter + length * j / 64, b = a + length / 64;
        const Vec3d p = ray.local_origin() + ray.local_direction() * a;
        const std::optional<Vec3d> q = s.deformation().inverse(p, DeformationChain::BeyondUndeformedBox::Gauge);
        ASSERT_TRUE(q);
        if (s.deformation().undeformed_box().contains(*q)) continue;
        ++beyond;
        EXPECT_EQ(ray.value(a), s.shape().gauge(*q) - 1);
        EXPECT_TRUE(ray.slope_bound(a, b).is_finite()) << "[" << a << ", " << b << "]";
        checked += check_bounds_hold_samples(ray, a, b);
    }
    EXPECT_GT(beyond, 8);
    EXPECT_GT(checked, 8 * 200);
    std::vector<Crossing> found;
    SuperquadricWork work;
    s.crossings(origin, direction, 0, 1e30, found, work);
    EXPECT_LE(work.search.halvings, 12u) << found.size() << " crossings";
}

// A stretch's end that rounding puts just beyond a face of the deformed box is taken at the face: g keeps its value
// there (not the constant of the outside) and the stretch its bound of g′.
TEST(SuperquadricAlongRay, PointsJustBeyondTheDeformedBoxAreTakenAtItsFace) {
    const Superquadric s = make_superquadric({0.4, 0.4, 0.4}, 0.3, 0.3, {Twist(3.14159 / 0.8, 0.4)});
    const IntervalBox& box = s.deformation().deformed_box();
    // Straight down through the top face, near the flat cap.
    const Vec3d origin{0.05, -0.03, 1}, direction{0, 0, -1};
    const SuperquadricAlongRay ray(s, origin, direction);
    const double face = origin.z - box.z.hi, beyond = face - 1e-9;
    const Vec3d at_face{origin.x, origin.y, box.z.hi};
    EXPECT_EQ(ray.value(beyond), s.local_field(at_face, DeformationChain::BeyondUndeformedBox::Gauge));
    EXPECT_GT(ray.value(beyond), 0);
    EXPECT_LT(ray.value(beyond), 1e-3);  // the cap lies just below the face
    EXPECT_EQ(ray.value_and_slope(beyond).value, ray.value(beyond));
    EXPECT_TRUE(ray.slope_bound(beyond, face + 0.01).is_finite());
    SuperquadricWork work;
    const std::optional<double> hit = s.first_crossing(origin, direction, 0, 10, work);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(*hit, face, 1e-3);
}

// The walk kept for the last stretch gives the bounds a fresh walk gives, whichever stretch was asked before.
TEST(SuperquadricAlongRay, BoundsDoNotDependOnTheStretchAskedBefore) {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> uniform(0, 1);
    const auto same = [](Interval x, Interval y) { return x.lo == y.lo && x.hi == y.hi; };
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
        const RandomCase c = random_case(random);
        const SuperquadricAlongRay ray(c.superquadric, c.origin, c.direction);
        const auto stretch = box_stretch(c.superquadric, ray);
        if (!stretch) continue;
        const double length = stretch->t_exit - stretch->t_enter;
        double previous_a = stretch->t_enter, previous_b = stretch->t_exit;
        for (int j = 0; j < 20; ++j) {
            const double width = length * std::pow(10.0, -3 * uniform(random));
            const double a = stretch->t_enter + (length - width) * uniform(random), b = a + width;
            const SuperquadricAlongRay fresh(c.superquadric, c.origin, c.direction);
            const Interval value = fresh.bound(a, b);
            const SuperquadricAlongRay fresh_for_slope(c.superquadric, c.origin, c.direction);
            const Interval slope = fresh_for_slope.slope_bound(a, b);
            EXPECT_TRUE(same(ray.slope_bound(a, b), slope));
            EXPECT_TRUE(same(ray.bound(a, b), value));
            EXPECT_TRUE(same(ray.slope_bound(a, b), slope));
            ray.bound(previous_a, previous_b);
            EXPECT_TRUE(same(ray.slope_bound(a, b), slope));
            previous_a = a, previous_b = b;
            ++checked;
        }
    }
    EXPECT_GT(checked, 1000);
}

TEST(SuperquadricAlongRay, AStretchProvenMonotoneHoldsOneCrossingOrNone) {
    int proven_with_crossing = 0, proven_without = 0;
    for_random_stretches(92, 300, [&](const Superquadric&, const SuperquadricAlongRay& ray, double a, double b) {
        const Interval slope = ray.slope_bound(a, b);
        if (!slope.excludes_zero()) return;
        const double direction = slope.lo > 0 ? 1 : -1;
        constexpr int kSamples = 1000;
        int sign_changes = 0;
        double previous = ray.value(a);
        for (int k = 1; k <= kSamples; ++k) {
            const double g = ray.value(a + (b - a) * k / kSamples);
            // Strictly monotone, up to rounding of g.
            EXPECT_GT(direction * (g - previous), -1e-13) << "[" << a << ", " << b << "]";
            sign_changes += (g < 0) != (previous < 0);
            previous = g;
        }
        const bool ends_differ = (ray.value(a) < 0) != (ray.value(b) < 0);
        EXPECT_EQ(sign_changes, ends_differ ? 1 : 0) << "[" << a << ", " << b << "]";
        ++(ends_differ ? proven_with_crossing : proven_without);
    });
    EXPECT_GT(proven_with_crossing, 300);
    EXPECT_GT(proven_without, 200);
}

// The crossings without the pairs closer together than `resolution`.
std::vector<Crossing> without_grazing_pairs(const std::vector<Crossing>& crossings, double resolution) {
    std::vector<Crossing> kept;
    for (std::size_t k = 0; k < crossings.size(); ++k) {
        if (k + 1 < crossings.size() && crossings[k + 1].t - crossings[k].t < resolution) {
            ++k;
            continue;
        }
        kept.push_back(crossings[k]);
    }
    return kept;
}

TEST(SuperquadricAlongRay, TheSearchFindsTheSameCrossingsAsWithoutTheSlopeBound) {
    std::mt19937 random(93);
    int crossings = 0;
    for (int i = 0; i < 400; ++i) {
        const RandomCase c = random_case(random);
        const Superquadric& s = c.superquadric;
        const SuperquadricAlongRay ray(s, c.origin, c.direction);
        const auto stretch = box_stretch(s, ray);
        if (!stretch) continue;
        std::vector<Crossing> with_slope;
        SuperquadricWork work;
        s.crossings(c.origin, c.direction, 0, 1e30, with_slope, work);
        // The search as it was before the slope bound: the same value and bound, g′ never known.
        const IntervalBox& box = s.deformation().deformed_box();
        const double extent = std::max({box.x.width(), box.y.width(), box.z.width()});
        const double resolution = Superquadric::kRelativeResolution * extent / length(ray.local_direction());
        std::vector<Crossing> without_slope;
        CrossingSearchWork old_work;
        search_crossings(
            stretch->t_enter, stretch->t_exit, ray.value(stretch->t_enter), ray.value(stretch->t_exit), resolution,
            false, [&](double t) { return ray.value(t); }, [&](double a, double b) { return ray.bound(a, b); },
            [](double, double) { return Interval::unbounded(); }, old_work, [&](const Crossing& found) {
                without_slope.push_back(found);
                return true;
            });
        // Two crossings closer than the resolution may be taken for a grazing contact (the search's rule), the
        // more so where the searches cut the ray differently (the shell's runs): compare the rest.
        with_slope = without_grazing_pairs(with_slope, resolution);
        without_slope = without_grazing_pairs(without_slope, resolution);
        ASSERT_EQ(with_slope.size(), without_slope.size()) << "case " << i;
        for (std::size_t k = 0; k < with_slope.size(); ++k) {
            EXPECT_NEAR(with_slope[k].t, without_slope[k].t, 1e-12 * std::abs(without_slope[k].t))
                << "case " << i << " crossing " << k;
            EXPECT_EQ(with_slope[k].entering, without_slope[k].entering) << "case " << i << " crossing " << k;
        }
        crossings += int(with_slope.size());
        EXPECT_LE(work.search.halvings, old_work.halvings) << "case " << i;
    }
    EXPECT_GT(crossings, 300);
}

}  // namespace
}  // namespace isotrace
