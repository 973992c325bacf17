#pragma once
// The crossings of a concave function g(t) on [t0, t1] without interval bounds: the inside function of a solid
// whose outside meets every piece of the ray in one interval (a superellipsoid with both exponents ≥ 2 between
// coordinate planes). Concavity settles what the general search (crossing_search.h) needs bounds for:
// - g ≥ 0 at both ends: g ≥ 0 throughout (a concave function is least at an end): no crossing.
// - a sign change: exactly one crossing (g rises, then falls), refined at once.
// - g < 0 at both ends: none or two crossings, around g's maximum. The tangents at two points that enclose the
//   maximum lie above g (Kelley's cutting planes), so where they meet is an upper bound of the maximum: below zero
//   it proves that there is no crossing; otherwise g is taken there, and either it is ≥ 0 (two crossings bracketed)
//   or its slope tells on which side the maximum lies, and the enclosure shrinks.
// Near a tangent contact the enclosure shrinks without settling: after kMaxSteps points (or where g′ is unknown,
// NaN, at a point that must decide a side) the caller falls back to the general search, which owns the rule for
// grazing contacts. An end's slope may be unknown or unbounded (a cusp at a coordinate plane): then only the other
// tangent bounds the maximum.
#include <cmath>
#include <cstdint>
#include <limits>

#include "geometry/field/crossing_search.h"
#include "renderer/math/safeguarded_newton.h"

namespace isotrace {

enum class ConcaveOutcome { Settled, Stopped, Unsettled };

// Visits the crossings of a concave g on [t0, t1] in increasing t (g0 = g(t0), g1 = g(t1); `at(t)` returns {value,
// derivative}, the value bit for bit the caller's g). Stopped when `visit` returned false; Unsettled when nothing
// was visited and the caller must search the segment itself.
// An end that lies on a coordinate plane where g has a cusp (`cusp_at_t0`, `cusp_at_t1`) gives no tangent: there
// the one-sided slope is unbounded, and the rounding of the point may even give the other side's. Segments no
// wider than `resolution` are left to the caller (their inner points are within rounding of their ends).
template <CrossingPrecision precision, class PointSlope, class Visit>
ConcaveOutcome visit_concave_crossings(double t0, double t1, double g0, double g1, bool cusp_at_t0, bool cusp_at_t1,
                                       double resolution, const PointSlope& at, CrossingSearchWork& work,
                                       Visit&& visit) {
    using crossing_search_detail::inside;
    // The one crossing between lo and hi, whose values differ in sign.
    const auto report = [&](double lo, double hi, double g_lo, double g_hi) {
        double t = 0.5 * (lo + hi);
        if constexpr (precision == CrossingPrecision::Refined) {
            ++work.crossings;
            t = g_lo == 0   ? lo
                : g_hi == 0 ? hi
                            : safeguarded_newton(at, lo, hi, g_lo, g_hi,
                                                 crossing_search_detail::RefinementTolerance{1e-15 * (hi - lo)},
                                                 &work.evaluations, std::numeric_limits<double>::quiet_NaN());
        }
        return visit(Crossing{t, inside(g_hi), lo, hi});
    };
    if (!inside(g0) && !inside(g1)) return ConcaveOutcome::Settled;
    if (inside(g0) != inside(g1)) return report(t0, t1, g0, g1) ? ConcaveOutcome::Settled : ConcaveOutcome::Stopped;

    if (!(t1 - t0 > resolution)) return ConcaveOutcome::Unsettled;
    constexpr int kMaxSteps = 40;
    double lo = t0, hi = t1, g_lo = g0, g_hi = g1;
    const auto slope_at = [&](double t) {
        ++work.evaluations;
        return at(t).derivative;
    };
    constexpr double unknown = std::numeric_limits<double>::quiet_NaN();  // no tangent to bound with
    double s_lo = cusp_at_t0 ? unknown : slope_at(t0), s_hi = cusp_at_t1 ? unknown : slope_at(t1);
    for (int step = 0; step < kMaxSteps; ++step) {
        // A slope that does not rise at lo (or fall at hi) puts the maximum there: g < 0 throughout.
        if (s_lo <= 0 || s_hi >= 0) return ConcaveOutcome::Settled;
        const bool tangent_lo = std::isfinite(s_lo), tangent_hi = std::isfinite(s_hi);
        double next = 0.5 * (lo + hi);
        if (tangent_lo && tangent_hi) {
            const double meet = (g_hi - g_lo + s_lo * lo - s_hi * hi) / (s_lo - s_hi);
            if (g_lo + s_lo * (meet - lo) < 0) return ConcaveOutcome::Settled;
            if (meet > lo && meet < hi) next = meet;
        } else if (tangent_hi && g_hi + s_hi * (lo - hi) < 0) {
            return ConcaveOutcome::Settled;
        } else if (tangent_lo && g_lo + s_lo * (hi - lo) < 0) {
            return ConcaveOutcome::Settled;
        }
        if (!(next > lo && next < hi)) return ConcaveOutcome::Unsettled;
        const auto there = at(next);
        ++work.evaluations;
        if (!inside(there.value)) {
            if (!report(lo, next, g_lo, there.value)) return ConcaveOutcome::Stopped;
            return report(next, hi, there.value, g_hi) ? ConcaveOutcome::Settled : ConcaveOutcome::Stopped;
        }
        if (there.derivative > 0) {
            lo = next, g_lo = there.value, s_lo = there.derivative;
        } else if (there.derivative < 0) {
            hi = next, g_hi = there.value, s_hi = there.derivative;
        } else {
            return there.derivative == 0 ? ConcaveOutcome::Settled : ConcaveOutcome::Unsettled;
        }
    }
    return ConcaveOutcome::Unsettled;
}

}  // namespace isotrace
