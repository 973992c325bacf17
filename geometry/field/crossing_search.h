#pragma once
// A guaranteed search for the sign changes of a function g(t) along a ray segment, given a point evaluator, an
// interval bound of g over any sub-segment and an interval bound of its derivative g′ (interval arithmetic).
// Sub-segments are visited nearest first: a sub-segment whose end values differ in sign holds a crossing; one
// whose bound excludes zero holds none and is dropped; the others are halved. A crossing bracket on which the
// bound of g′ excludes zero holds exactly one crossing (g is strictly monotone there) and is refined at once;
// otherwise it is halved further until it is no wider than `resolution` (so no earlier pair of crossings hides
// in it) before it is refined. A sub-segment without a sign change holds no crossing when g is proven monotone
// on it, or when its end values and the bound of g′ leave no room to reach zero in between (a mean-value test,
// much tighter than the interval bound on short sub-segments). Refinement is the Illinois variant of regula falsi with bisection steps whenever it stalls. A
// sub-segment narrower than `resolution` whose bound still straddles zero without a sign change at its ends is a
// grazing contact (two crossings closer than the resolution, or none) and is not reported — the project's rule
// for tangent contacts (docs/decisions.md). When the caller knows that {g < 0} meets the ray in one interval (a
// convex solid), a sign change brackets exactly one crossing and is refined at once. Where the caller can give g′
// at a point too, refinement takes safeguarded Newton steps instead (renderer/math/safeguarded_newton.h).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "renderer/math/interval.h"
#include "renderer/math/safeguarded_newton.h"

namespace isotrace {

struct Crossing {
    double t;
    bool entering;  // g goes from ≥ 0 (outside) to < 0 (inside)
    // The bracket it was found in (lo ≤ t ≤ hi); a search that does not refine reports its midpoint as t.
    double lo = t, hi = t;

    // Whether the crossing lies in the ray's range (t_near, t_far) whatever t refining its bracket would give, up to
    // the float t_far a hit is reported in: then an occlusion query is settled without refining it.
    bool settles_occlusion(double t_near, float t_far) const { return lo > t_near && float(hi) < t_far; }
};

// Whether the search locates each crossing to a few ulps, only reports the bracket that holds it, or reports the
// first sub-segment whose ends differ in sign as it is (`SignChange`: the sub-segments before it hold no crossing, so
// it holds the first one, with an even number of others perhaps; enough for a query that asks whether there is a
// crossing in a range, such as an occlusion test, and no bound of g′ is taken to isolate it).
enum class CrossingPrecision { Refined, Bracketed, SignChange };

struct CrossingSearchWork {
    std::uint64_t interval_bounds = 0;
    std::uint64_t slope_bounds = 0;
    std::uint64_t slope_proofs = 0;  // sub-segments settled by the bound of g′ (monotone, or keeping their sign)
    std::uint64_t evaluations = 0;  // all point values: halvings and refinement steps
    std::uint64_t halvings = 0;
    std::uint64_t crossings = 0;    // brackets refined
};

namespace crossing_search_detail {

inline bool inside(double g) { return g < 0; }

// A crossing in [lo, hi], whose end values differ in sign, located to a few ulps of t (Illinois: when the same
// end is replaced twice in a row the other end's value is halved; a bisection step whenever the bracket has not
// halved in three steps; a step never closer to an end than half the final width, so that the bracket closes
// as soon as the secant has converged from one side).
template <class Value>
double refine(double lo, double hi, double g_lo, double g_hi, const Value& value, CrossingSearchWork& work) {
    const double floor = 1e-15 * (hi - lo);
    double width_at_last_halving = hi - lo;
    int steps_since_halving = 0, last_replaced = 0;  // -1: lo, +1: hi
    for (int i = 0; i < 200; ++i) {
        const double tolerance = 4e-16 * std::max(std::abs(lo), std::abs(hi)) + floor;
        if (hi - lo <= tolerance) break;
        // The secant step measured from an end: its rounding error is relative to the bracket's width, not to t.
        double t = hi - g_hi * ((hi - lo) / (g_hi - g_lo));
        if (!(t >= lo && t <= hi) || steps_since_halving >= 3) t = 0.5 * (lo + hi);
        // A step within the tolerance of an end would leave the other end where it is: step half the tolerance
        // inside instead, so that a secant converging from one side closes the bracket on the next step.
        t = std::clamp(t, lo + 0.5 * tolerance, hi - 0.5 * tolerance);
        const double g = value(t);
        ++work.evaluations;
        if (inside(g) == inside(g_lo)) {
            lo = t;
            g_lo = g;
            if (last_replaced == -1) g_hi *= 0.5;
            last_replaced = -1;
        } else {
            hi = t;
            g_hi = g;
            if (last_replaced == 1) g_lo *= 0.5;
            last_replaced = 1;
        }
        if (hi - lo <= 0.5 * width_at_last_halving) {
            width_at_last_halving = hi - lo;
            steps_since_halving = 0;
        } else {
            ++steps_since_halving;
        }
    }
    return 0.5 * (lo + hi);
}

// The least value g can take on [0, width] given g(0) = g_lo, g(width) = g_hi and g′ ∈ slope with slope.lo < 0 <
// slope.hi: where the steepest descent from the left end meets the steepest ascent into the right end.
inline double least_value(double width, double g_lo, double g_hi, Interval slope) {
    const double x = (g_hi - g_lo - slope.hi * width) / (slope.lo - slope.hi);
    return g_lo + slope.lo * std::clamp(x, 0.0, width);
}

// Whether g, with the same sign at both ends of a sub-segment, provably keeps it in between.
inline bool keeps_sign(double width, double g_lo, double g_hi, Interval slope) {
    if (!slope.is_finite()) return false;
    if (!inside(g_lo)) return least_value(width, g_lo, g_hi, slope) > 0;
    return -least_value(width, -g_lo, -g_hi, Interval{-slope.hi, -slope.lo}) < 0;
}

// The bracket width refinement stops at, as for regula falsi: a few ulps of t, or 10⁻¹⁵ of the first bracket.
struct RefinementTolerance {
    double floor;
    double width_at(double t) const { return 4e-16 * std::abs(t) + floor; }
};

}  // namespace crossing_search_detail

// For search_crossings without point derivatives.
struct NoPointSlope {};

// Visits the crossings of g in [t0, t1] in increasing t; g0 = g(t0), g1 = g(t1). With CrossingPrecision::Bracketed
// every crossing is reported with the bracket that holds exactly it (or a pair closer than the resolution); with
// SignChange, with the first sub-segment found to hold it.
// `bound(a, b)` returns an Interval containing g over [a, b], `slope(a, b)` one containing g′ wherever g is
// differentiable on [a, b] (g continuous there, differentiable but at finitely many points; an unbounded interval
// when nothing is known); `visit(Crossing)` returns false to stop. Returns false when stopped. With
// `point_slope(t)` returning {value, derivative} (value bit for bit value(t); derivative NaN where unknown),
// brackets are refined by Newton steps.
template <CrossingPrecision precision = CrossingPrecision::Refined, class Value, class Bound, class Slope, class Visit,
          class PointSlope = NoPointSlope>
bool search_crossings(double t0, double t1, double g0, double g1, double resolution, bool convex, const Value& value,
                      const Bound& bound, const Slope& slope, CrossingSearchWork& work, Visit&& visit,
                      const PointSlope& point_slope = {}) {
    using crossing_search_detail::inside;
    struct Segment {
        double lo, hi, g_lo, g_hi;
    };
    // Whether the bound of g′ settles the sub-segment: monotone, or (without a sign change) keeping its sign.
    const auto settled_by_slope = [&](const Segment& s, bool sign_change) {
        ++work.slope_bounds;
        const Interval g_slope = slope(s.lo, s.hi);
        const bool proven = g_slope.excludes_zero() ||
                            (!sign_change && crossing_search_detail::keeps_sign(s.hi - s.lo, s.g_lo, s.g_hi, g_slope));
        work.slope_proofs += proven;
        return proven;
    };
    constexpr int kMaxDepth = 96;
    Segment stack[kMaxDepth + 1];
    int top = 0;
    stack[top++] = {t0, t1, g0, g1};
    while (top > 0) {
        const Segment s = stack[--top];
        const bool sign_change = inside(s.g_lo) != inside(s.g_hi);
        const double mid = 0.5 * (s.lo + s.hi);
        const bool narrow =
            s.hi - s.lo <= resolution || top >= kMaxDepth - 1 || !(mid > s.lo && mid < s.hi);  // or no double between
        if (sign_change &&
            (narrow || convex || precision == CrossingPrecision::SignChange || settled_by_slope(s, true))) {
            double t = 0.5 * (s.lo + s.hi);
            if constexpr (precision == CrossingPrecision::Refined) {
                ++work.crossings;
                if constexpr (std::is_same_v<PointSlope, NoPointSlope>) {
                    t = crossing_search_detail::refine(s.lo, s.hi, s.g_lo, s.g_hi, value, work);
                } else {
                    t = safeguarded_newton(point_slope, s.lo, s.hi, s.g_lo, s.g_hi,
                                           crossing_search_detail::RefinementTolerance{1e-15 * (s.hi - s.lo)},
                                           &work.evaluations, std::numeric_limits<double>::quiet_NaN());
                }
            }
            if (!visit(Crossing{t, inside(s.g_hi), s.lo, s.hi})) return false;
            continue;
        }
        if (!sign_change) {
            ++work.interval_bounds;
            const Interval range = bound(s.lo, s.hi);
            if (range.lo >= 0 || range.hi < 0 || narrow || settled_by_slope(s, false)) continue;
        }
        const double g_mid = value(mid);
        ++work.evaluations;
        ++work.halvings;
        stack[top++] = {mid, s.hi, g_mid, s.g_hi};  // the far half waits below the near one
        stack[top++] = {s.lo, mid, s.g_lo, g_mid};
    }
    return true;
}

}  // namespace isotrace
