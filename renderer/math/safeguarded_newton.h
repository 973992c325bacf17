#pragma once
// Refines a root inside a bracket where a function changes sign: Newton steps while they stay inside the
// (shrinking) bracket and make progress, bisection otherwise. Always converges; quadratically when Newton works.
// Shared by the polynomial root finder (blob pieces, tori) and the crossing search of implicit surfaces that can
// give their derivative along the ray (superquadrics).
#include <cmath>
#include <cstdint>

namespace isotrace {

// evaluate(t) returns {value, derivative} (members of those names); tolerance.width_at(t) the width within which t
// is close enough. Requires lo < hi and value_at_lo, value_at_hi non-zero with opposite signs. Returns t ∈ [lo, hi]
// with a zero value or within tolerance.width_at(t) of a sign change. Counts its evaluations in *steps when given.
// Starts at first_guess when it lies in (lo, hi), else where the secant through the bracket's ends meets zero.
template <class Evaluate, class Tolerance>
double safeguarded_newton(const Evaluate& evaluate, double lo, double hi, double value_at_lo, double value_at_hi,
                          const Tolerance& tolerance, std::uint64_t* steps, double first_guess) {
    constexpr int kMaxIterations = 2100;  // enough bisections to shrink any finite double interval to adjacent doubles
    const bool rising = value_at_lo < 0;
    // The secant through the bracket is a better first guess than the midpoint on monotone pieces.
    double t = first_guess > lo && first_guess < hi ? first_guess
                                                    : lo + (hi - lo) * (value_at_lo / (value_at_lo - value_at_hi));
    if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
    double step_before_last = hi - lo, last_step = hi - lo;
    bool newton_before = false;  // the last step was Newton's
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        if (steps) ++*steps;
        const auto at = evaluate(t);
        if (at.value == 0) return t;
        ((at.value < 0) == rising ? lo : hi) = t;
        if (hi - lo <= tolerance.width_at(t)) return 0.5 * (lo + hi);
        const double newton = t - at.value / at.derivative;
        // A step too small to move t: the value is zero within its rounding, here. (Left to bisection, which would
        // be right too, it halves a bracket the value's rounding cannot resolve, some 8 steps.)
        if (newton == t) return t;
        // Newton is rejected when it leaves the bracket or fails to halve the step before last (slow convergence
        // near flat spots); bisection then guarantees progress.
        if (newton > lo && newton < hi && std::abs(newton - t) < 0.5 * step_before_last) {
            step_before_last = last_step;
            last_step = std::abs(newton - t);
            t = newton;
            if (last_step <= tolerance.width_at(t)) return t;
            // Two Newton steps in a row: the error left after this one is about C·step² with C ≈ step/previous², so
            // when step³/previous² is below 10⁻⁴ of the tolerance, another step would only confirm t (on blob hits
            // that step is often the last; docs/benchmarks.md, "Blob groups"). The estimate can be off where
            // convergence is not yet quadratic: at 10⁻², a random bracket of bracketed_root_test ended outside its
            // tolerance.
            if (newton_before &&
                last_step * last_step * last_step <= 1e-4 * tolerance.width_at(t) * step_before_last * step_before_last)
                return t;
            newton_before = true;
        } else {
            step_before_last = last_step;
            last_step = 0.5 * (hi - lo);
            t = 0.5 * (lo + hi);
            newton_before = false;
        }
    }
    return t;
}

}  // namespace isotrace
