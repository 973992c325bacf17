#pragma once
// Refines a root inside a bracket where the polynomial changes sign by safeguarded Newton steps
// (renderer/math/safeguarded_newton.h). Always converges; quadratically when Newton works.
#include <limits>

#include "geometry/polynomial/polynomial.h"
#include "geometry/polynomial/polynomial_root.h"

namespace isotrace {

// Requires lo < hi and value_at_lo, value_at_hi non-zero with opposite signs. Returns t ∈ [lo, hi] with
// p(t) = 0 or within tolerance.width_at(t) of a sign change of p. Adds its steps to `work` when given. The search
// starts at first_guess when it lies in (lo, hi), else where the secant through the bracket's ends meets zero.
double refine_bracketed_root(const Polynomial& p, double lo, double hi, double value_at_lo, double value_at_hi,
                             const RootTolerance& tolerance, RootFinderWork* work = nullptr,
                             double first_guess = std::numeric_limits<double>::quiet_NaN());

}  // namespace isotrace
