#include "geometry/polynomial/bracketed_root.h"

#include <array>
#include <cmath>
#include <cstdint>

#include "renderer/math/safeguarded_newton.h"

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

}  // namespace

double refine_bracketed_root(const Polynomial& p, double lo, double hi, double value_at_lo, double value_at_hi,
                             const RootTolerance& tolerance, RootFinderWork* work, double first_guess) {
    std::uint64_t* const steps = work ? &work->iterations : nullptr;
    if (p.degree() <= 7)
        return safeguarded_newton(EstrinSeven(p), lo, hi, value_at_lo, value_at_hi, tolerance, steps, first_guess);
    return safeguarded_newton([&](double t) { return p.evaluate_with_derivative(t); }, lo, hi, value_at_lo,
                              value_at_hi, tolerance, steps, first_guess);
}

}  // namespace isotrace
