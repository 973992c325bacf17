#include "geometry/polynomial/bracketed_root.h"

#include <array>
#include <cmath>

namespace isotrace {
namespace {

// p and p' of a polynomial of degree ≤ 7 by Estrin's scheme: pairs, then pairs of pairs, so the value's chain of
// dependent operations is three multiply–adds long where Horner's is seven (each Newton step of a blob hit waits
// on it). Rounds differently from Horner, to a few ulps of the terms' magnitudes.
class EstrinSeven {
public:
    explicit EstrinSeven(const Polynomial& p) {
        for (int i = 0; i <= 7; ++i) value_[i] = i <= p.degree() ? p[i] : 0.0;
        for (int i = 0; i < 7; ++i) slope_[i] = (i + 1) * value_[i + 1];
    }
    ValueAndDerivative operator()(double t) const {
        const double t2 = t * t, t4 = t2 * t2;
        return {of(value_, t, t2, t4), of(slope_, t, t2, t4)};
    }

private:
    static double of(const std::array<double, 8>& c, double t, double t2, double t4) {
        return ((c[0] + c[1] * t) + (c[2] + c[3] * t) * t2) + ((c[4] + c[5] * t) + (c[6] + c[7] * t) * t2) * t4;
    }
    std::array<double, 8> value_, slope_{};
};

// The search, for p given by evaluate(t) → ValueAndDerivative.
template <class Evaluate>
double refine(const Evaluate& evaluate, double lo, double hi, double value_at_lo, double value_at_hi,
              const RootTolerance& tolerance, RootFinderWork* work, double first_guess) {
    constexpr int kMaxIterations = 2100;  // enough bisections to shrink any finite double interval to adjacent doubles
    const bool rising = value_at_lo < 0;
    // The secant through the bracket is a better first guess than the midpoint on monotone pieces.
    double t = first_guess > lo && first_guess < hi ? first_guess
                                                    : lo + (hi - lo) * (value_at_lo / (value_at_lo - value_at_hi));
    if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
    double step_before_last = hi - lo, last_step = hi - lo;
    bool newton_before = false;  // the last step was Newton's
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        if (work) ++work->iterations;
        const ValueAndDerivative at = evaluate(t);
        if (at.value == 0) return t;
        ((at.value < 0) == rising ? lo : hi) = t;
        if (hi - lo <= tolerance.width_at(t)) return 0.5 * (lo + hi);
        const double newton = t - at.value / at.derivative;
        // A step too small to move t: p(t) is zero within its rounding, here. (Left to bisection, which would be
        // right too, it halved a bracket p's rounding cannot resolve, some 8 steps: with Estrin's rounding, 1.6 M
        // steps instead of 0.56 M on blobs_1k's blob hits.)
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

}  // namespace

double refine_bracketed_root(const Polynomial& p, double lo, double hi, double value_at_lo, double value_at_hi,
                             const RootTolerance& tolerance, RootFinderWork* work, double first_guess) {
    if (p.degree() <= 7) return refine(EstrinSeven(p), lo, hi, value_at_lo, value_at_hi, tolerance, work, first_guess);
    return refine([&](double t) { return p.evaluate_with_derivative(t); }, lo, hi, value_at_lo, value_at_hi,
                  tolerance, work, first_guess);
}

}  // namespace isotrace
