#include "geometry/polynomial/bracketed_root.h"

#include <cmath>

namespace isotrace {
namespace {

// Enough bisections to shrink any finite double interval to adjacent doubles.
constexpr int kMaxIterations = 2100;

}  // namespace

double refine_bracketed_root(const Polynomial& p, double lo, double hi, double value_at_lo, double value_at_hi,
                             const RootTolerance& tolerance, RootFinderWork* work) {
    const bool rising = value_at_lo < 0;
    // The secant through the bracket is a better first guess than the midpoint on monotone pieces.
    double t = lo + (hi - lo) * (value_at_lo / (value_at_lo - value_at_hi));
    if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
    double step_before_last = hi - lo, last_step = hi - lo;
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        if (work) ++work->iterations;
        const auto [value, slope] = p.evaluate_with_derivative(t);
        if (value == 0) return t;
        ((value < 0) == rising ? lo : hi) = t;
        if (hi - lo <= tolerance.width_at(t)) return 0.5 * (lo + hi);
        const double newton = t - value / slope;
        // Newton is rejected when it leaves the bracket or fails to halve the step before last (slow convergence
        // near flat spots); bisection then guarantees progress.
        if (newton > lo && newton < hi && std::abs(newton - t) < 0.5 * step_before_last) {
            step_before_last = last_step;
            last_step = std::abs(newton - t);
            t = newton;
            if (last_step <= tolerance.width_at(t)) return t;
        } else {
            step_before_last = last_step;
            last_step = 0.5 * (hi - lo);
            t = 0.5 * (lo + hi);
        }
    }
    return t;
}

}  // namespace isotrace
