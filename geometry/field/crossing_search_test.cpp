// The guaranteed crossing search on functions with known roots: a pair of close crossings hidden inside a
// sign-change bracket is still found first, every crossing is visited in order with its direction, a convex
// caller's bracket and a bracket proven monotone by the derivative bound are refined at once (with the same
// crossings as without the derivative bound), a root the secant approaches from one side is closed in at once, an
// occlusion query's search reports the first stretch whose ends differ in sign as it is, and visiting stops when
// asked.
#include "geometry/field/crossing_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>
#include <vector>

namespace isotrace {
namespace {

// g(t) = −(t − r0)(t − r1)(t − r2): positive (outside) before r0, with an exact interval extension.
struct Cubic {
    double r0, r1, r2;
    double operator()(double t) const { return -(t - r0) * (t - r1) * (t - r2); }
    Interval bound(double a, double b) const {
        const Interval t{a, b};
        const Interval product = (t + (-r0)) * (t + (-r1)) * (t + (-r2));
        return {-product.hi, -product.lo};
    }
    // g′ = −[(t − r1)(t − r2) + (t − r0)(t − r2) + (t − r0)(t − r1)].
    Interval slope(double a, double b) const {
        const Interval t{a, b}, d0 = t + (-r0), d1 = t + (-r1), d2 = t + (-r2);
        const Interval sum = d1 * d2 + d0 * d2 + d0 * d1;
        return {-sum.hi, -sum.lo};
    }
};

// How the search may use g′: not at all (the search before the derivative bound), or its interval bound.
enum class SlopeUse { None, Bound };

std::vector<Crossing> all_crossings(const Cubic& g, double t0, double t1, double resolution, bool convex = false,
                                    SlopeUse use = SlopeUse::Bound, CrossingSearchWork* work_out = nullptr) {
    std::vector<Crossing> found;
    CrossingSearchWork work;
    search_crossings(
        t0, t1, g(t0), g(t1), resolution, convex, g, [&](double a, double b) { return g.bound(a, b); },
        [&](double a, double b) { return use == SlopeUse::Bound ? g.slope(a, b) : Interval::unbounded(); }, work,
        [&](const Crossing& c) {
            found.push_back(c);
            return true;
        });
    if (work_out) *work_out = work;
    return found;
}

TEST(SuperquadricCrossingSearch, ACloseEarlyPairInsideASignChangeIsFoundFirst) {
    // The ends differ in sign because of the last root; the first two are 1e-6 apart, far above the resolution.
    const Cubic g{0.3, 0.300001, 0.7};
    const std::vector<Crossing> found = all_crossings(g, 0, 1, 1e-8);
    ASSERT_EQ(found.size(), 3u);
    EXPECT_NEAR(found[0].t, 0.3, 1e-14);
    EXPECT_NEAR(found[1].t, 0.300001, 1e-14);
    EXPECT_NEAR(found[2].t, 0.7, 1e-14);
    EXPECT_TRUE(found[0].entering);
    EXPECT_FALSE(found[1].entering);
    EXPECT_TRUE(found[2].entering);
}

TEST(SuperquadricCrossingSearch, TheConvexShortcutRefinesTheBracketItIsGiven) {
    // Told (wrongly, on purpose) that the function is convex, the search trusts the sign change of the ends and
    // reports one crossing: this is why the shortcut is only taken for convex solids.
    const Cubic g{0.3, 0.300001, 0.7};
    const std::vector<Crossing> found = all_crossings(g, 0, 1, 1e-8, true);
    ASSERT_EQ(found.size(), 1u);
    // A convex case: one entry at 0.25 of a parabola that stays negative up to t = 1.
    const Cubic parabola_like{0.25, 2, 3};  // negative on (0.25, 2)
    const std::vector<Crossing> entry = all_crossings(parabola_like, 0, 1, 1e-8, true);
    ASSERT_EQ(entry.size(), 1u);
    EXPECT_NEAR(entry[0].t, 0.25, 1e-14);
}

TEST(SuperquadricCrossingSearch, ABracketProvenMonotoneIsRefinedAtOnceToTheSameCrossings) {
    // Three well separated roots: every bracket that isolates one is proven monotone after a few halvings, where
    // the search without the derivative bound halves each down to the resolution.
    const Cubic g{0.21, 0.5, 0.83};
    CrossingSearchWork with_slope, without_slope;
    const std::vector<Crossing> fast = all_crossings(g, 0, 1, 1e-9, false, SlopeUse::Bound, &with_slope);
    const std::vector<Crossing> slow = all_crossings(g, 0, 1, 1e-9, false, SlopeUse::None, &without_slope);
    ASSERT_EQ(fast.size(), 3u);
    ASSERT_EQ(slow.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(fast[i].t, slow[i].t, 1e-14);
        EXPECT_EQ(fast[i].entering, slow[i].entering);
    }
    EXPECT_NEAR(fast[0].t, 0.21, 1e-14);
    EXPECT_GT(with_slope.slope_proofs, 0u);
    EXPECT_EQ(without_slope.slope_proofs, 0u);
    EXPECT_LT(with_slope.halvings * 4, without_slope.halvings);
}

TEST(SuperquadricCrossingSearch, EndValuesAndTheSlopeBoundGiveTheLeastValueInBetween) {
    using crossing_search_detail::keeps_sign;
    using crossing_search_detail::least_value;
    // |t − ½| + c on [0, 1] with g′ ∈ [−1, 1]: the least value is exactly c.
    EXPECT_DOUBLE_EQ(least_value(1, 0.6, 0.6, {-1, 1}), 0.1);
    EXPECT_TRUE(keeps_sign(1, 0.6, 0.6, {-1, 1}));
    EXPECT_FALSE(keeps_sign(1, 0.45, 0.45, {-1, 1}));  // c = −0.05: it may dip inside
    // The same mirrored: inside at both ends, provably inside between, or not.
    EXPECT_TRUE(keeps_sign(1, -0.6, -0.6, {-1, 1}));
    EXPECT_FALSE(keeps_sign(1, -0.45, -0.45, {-1, 1}));
    // Uneven slopes: from 0.2 falling at most 0.1 per unit, rising into 0.9 at most 2 per unit.
    EXPECT_GT(least_value(1, 0.2, 0.9, {-0.1, 2}), 0);
    EXPECT_FALSE(keeps_sign(1, 0.2, 0.9, Interval::unbounded()));
}

TEST(SuperquadricCrossingSearch, AGapProvenByTheSlopeBoundIsNotHalvedDownToTheResolution) {
    // (t − ½)² + 0.01 stays outside; its interval bound is useless on purpose, its slope bound exact. The segment
    // around the minimum is never monotone, but its end values and slopes show it cannot reach zero.
    const auto g = [](double t) { return (t - 0.5) * (t - 0.5) + 0.01; };
    CrossingSearchWork work;
    std::vector<Crossing> found;
    search_crossings(
        0, 1, g(0), g(1), 1e-9, false, g, [](double, double) { return Interval{-1, 2}; },
        [](double a, double b) { return Interval{2 * (a - 0.5), 2 * (b - 0.5)}; }, work,
        [&](const Crossing& c) {
            found.push_back(c);
            return true;
        });
    EXPECT_TRUE(found.empty());
    EXPECT_LE(work.halvings, 4u);
}

TEST(SuperquadricCrossingSearch, ARootApproachedFromOneSideClosesTheBracketAtOnce) {
    // A distance-like function (a hyperbola: 1 − √(t² + ¼), root √¾) along which the secant steps all land on one
    // side of the root: refined to a few ulps in 9 evaluations, where bisecting the far end in took 36.
    const auto g = [](double t) { return 1 - std::sqrt(t * t + 0.25); };
    CrossingSearchWork work;
    const double t = crossing_search_detail::refine(0, 3, g(0), g(3), g, work);
    EXPECT_NEAR(t, std::sqrt(0.75), 2e-15);  // the refinement stops at 10⁻¹⁵ of the bracket it was given
    EXPECT_LE(work.evaluations, 12u);
}

TEST(SuperquadricCrossingSearch, PairsCloserThanTheResolutionMayBeTakenForAGrazingContact) {
    // Both ends outside, two crossings 1e-10 apart: below a resolution of 1e-6 the pair is a grazing contact.
    const Cubic g{0.4, 0.4 + 1e-10, 5};
    EXPECT_TRUE(all_crossings(g, 0, 1, 1e-6).empty());
    // With a finer resolution it is found.
    EXPECT_EQ(all_crossings(g, 0, 1, 1e-12).size(), 2u);
}

// Three crossings in a stretch whose ends differ in sign: with SignChange the stretch is reported as it is, without a
// bound of g′ or a halving; Bracketed isolates the first crossing.
TEST(SuperquadricCrossingSearch, SignChangeReportsTheFirstStretchWhoseEndsDifferInSign) {
    const Cubic g{0.3, 0.5, 0.7};
    const auto first = [&](auto precision, CrossingSearchWork& work) {
        Crossing found{-1, false};
        search_crossings<decltype(precision)::value>(
            0, 1, g(0), g(1), 1e-8, false, g, [&](double a, double b) { return g.bound(a, b); },
            [&](double a, double b) { return g.slope(a, b); }, work, [&](const Crossing& c) {
                found = c;
                return false;
            });
        return found;
    };
    CrossingSearchWork any_work, bracketed_work;
    const Crossing any = first(std::integral_constant<CrossingPrecision, CrossingPrecision::SignChange>{}, any_work);
    EXPECT_EQ(any.lo, 0);
    EXPECT_EQ(any.hi, 1);
    EXPECT_TRUE(any.entering);
    EXPECT_EQ(any_work.slope_bounds, 0u);
    EXPECT_EQ(any_work.halvings, 0u);
    const Crossing bracketed = first(std::integral_constant<CrossingPrecision, CrossingPrecision::Bracketed>{}, bracketed_work);
    EXPECT_LE(bracketed.lo, 0.3);
    EXPECT_GE(bracketed.hi, 0.3);
    EXPECT_LT(bracketed.hi, 0.5);
    EXPECT_GT(bracketed_work.halvings, 0u);
}

TEST(SuperquadricCrossingSearch, VisitingStopsWhenAsked) {
    const Cubic g{0.2, 0.5, 0.8};
    int visits = 0;
    CrossingSearchWork work;
    const bool finished = search_crossings(
        0, 1, g(0), g(1), 1e-9, false, g, [&](double a, double b) { return g.bound(a, b); },
        [&](double a, double b) { return g.slope(a, b); }, work, [&](const Crossing&) { return ++visits < 2; });
    EXPECT_FALSE(finished);
    EXPECT_EQ(visits, 2);
    EXPECT_GT(work.interval_bounds, 0u);
}

}  // namespace
}  // namespace isotrace
