#pragma once
// The crossings of a convex function g(t) on [t0, t1] (the inside function of a convex solid along a ray) by
// monotone Newton marches, without interval bounds. Convexity settles everything the general search
// (crossing_search.h) needs bounds for:
// - g < 0 at both ends: g < 0 throughout (no crossing); a convex g meets zero at most twice.
// - outside at t0 (g(t0) ≥ 0): Newton steps from t0 never pass the first root (the tangent of a convex function
//   lies below it), so they climb to it monotonically; a step with g′ ≥ 0 proves that g stays positive from there
//   on, a step beyond t1 that the root lies beyond t1. The exit, when g(t1) ≥ 0, is the same march from t1 backward.
// - inside at t0: the only crossing is the exit, marched from t1 backward when g(t1) ≥ 0.
// Near a tangent contact Newton converges only linearly: after kMaxSteps steps (or where g′ is unknown, NaN) the
// march gives up and the caller falls back to the general search, which owns the rule for grazing contacts.
#include <cmath>
#include <cstdint>
#include <optional>

#include "geometry/field/crossing_search.h"
#include "renderer/math/safeguarded_newton.h"

namespace isotrace {
namespace convex_crossings_detail {

enum class March { Root, None, Unknown };

struct MarchResult {
    March outcome;
    double t = 0;
};

// The first root of g(a + direction·s) for s in [0, length], g(a) ≥ 0; `at(t)` returns {value, derivative} in t.
template <class PointSlope>
MarchResult march(const PointSlope& at, double a, double g_a, double slope_a, double direction, double length,
                  CrossingSearchWork& work) {
    constexpr int kMaxSteps = 40;
    const crossing_search_detail::RefinementTolerance tolerance{1e-15 * length};
    double s = 0, g = g_a, slope = slope_a * direction, previous_step = length;
    if (g == 0) return {March::Root, a};
    for (int step = 0; step < kMaxSteps; ++step) {
        if (std::isnan(slope)) return {March::Unknown};
        if (slope >= 0) return {March::None};  // g ≥ g(s) > 0 from here on
        const double next = s - g / slope;
        if (!(next <= length)) return {March::None};  // the root lies beyond the end
        const double t_next = a + direction * next;
        const auto value = at(t_next);
        ++work.evaluations;
        const double moved = next - s;
        if (value.value <= 0) {
            if (value.value == 0 || moved <= tolerance.width_at(t_next)) return {March::Root, t_next};
            // Rounding made the step overshoot: the root is bracketed; polish it there.
            const double t_here = a + direction * s;
            const double lo = std::min(t_here, t_next), hi = std::max(t_here, t_next);
            const double g_lo = direction > 0 ? g : value.value, g_hi = direction > 0 ? value.value : g;
            return {March::Root, safeguarded_newton(at, lo, hi, g_lo, g_hi, tolerance, &work.evaluations,
                                                    std::numeric_limits<double>::quiet_NaN())};
        }
        // Converged: the step is below the tolerance, or quadratic convergence makes the next one negligible.
        if (moved <= tolerance.width_at(t_next) ||
            (step > 0 && moved * moved * moved <= 1e-4 * tolerance.width_at(t_next) * previous_step * previous_step))
            return {March::Root, t_next};
        previous_step = moved;
        s = next;
        g = value.value;
        slope = value.derivative * direction;
    }
    return {March::Unknown};
}

}  // namespace convex_crossings_detail

// Visits the crossings of a convex g on [t0, t1] in increasing t (`at(t)` returns {value, derivative}, the value bit
// for bit the caller's g): the first only, or all of them. g is taken at t1 only when the answer depends on it: not
// when the ray enters from outside and the first crossing is all that is asked, nor when it never enters. Returns
// false when the march could not settle the segment; then nothing was visited and the caller runs the general search.
template <class PointSlope, class Visit>
bool visit_convex_crossings(double t0, double t1, const PointSlope& at, bool first_only, CrossingSearchWork& work,
                            Visit&& visit) {
    using convex_crossings_detail::March;
    using convex_crossings_detail::march;
    const double length = t1 - t0;
    const auto start = at(t0);
    ++work.evaluations;
    std::optional<double> entry;
    if (start.value >= 0) {
        const auto found = march(at, t0, start.value, start.derivative, 1, length, work);
        if (found.outcome == March::Unknown) return false;
        if (found.outcome == March::None) return true;
        entry = found.t;
    }
    const auto only_the_entry = [&] {
        if (!entry) return true;  // inside at both ends: no crossing
        ++work.crossings;
        visit(Crossing{*entry, true});
        return true;
    };
    if (entry && first_only) return only_the_entry();
    const auto end = at(t1);
    ++work.evaluations;
    if (!(end.value >= 0)) return only_the_entry();
    const auto exit = march(at, t1, end.value, end.derivative, -1, length, work);
    if (exit.outcome != March::Root) return false;          // a crossing is known to lie before t1
    if (entry && !(exit.t > *entry)) return false;          // a tangent contact: the general search decides
    work.crossings += entry ? 2 : 1;
    if (entry && !visit(Crossing{*entry, true})) return true;
    visit(Crossing{exit.t, false});
    return true;
}

}  // namespace isotrace
