#pragma once
// Roots of a polynomial in an interval after Yuksel, "High-Performance Polynomial Root Finding for Graphics"
// (HPG 2022): the roots of p' split [a,b] into pieces where p is monotone, found the same way from p'' and so on
// down to a linear derivative; each piece whose ends differ in sign holds exactly one root, which a bracketed
// Newton iteration finds. No heap, no exceptions.
//
// Semantics shared by both functions:
// - The interval is closed: a root exactly at a or b (an end whose value is within rounding of zero) is reported.
// - Leading terms negligible on [a,b] are dropped first (a near-zero leading coefficient is a lower degree).
// - Tangent roots: a double root touches zero without a sign change, and in double precision it is as likely to
//   be two close roots or none. A critical point whose |p| is within the evaluation rounding bound is reported as
//   a root with `tangent` set (and the pieces on either side are not searched again, so it is reported once).
//   A local extremum further from zero than rounding is not a root.
// - The zero polynomial and non-zero constants report no roots.
#include <optional>

#include "geometry/polynomial/polynomial.h"
#include "geometry/polynomial/polynomial_root.h"

namespace isotrace {

// The smallest root in [a, b] (a ≤ b), or nothing. Refinement steps are added to `work` when given.
std::optional<PolynomialRoot> first_root(const Polynomial& p, double a, double b, const RootTolerance& tolerance = {},
                                         RootFinderWork* work = nullptr);

// All roots in [a, b] (a ≤ b), ascending.
PolynomialRoots all_roots(const Polynomial& p, double a, double b, const RootTolerance& tolerance = {},
                          RootFinderWork* work = nullptr);

}  // namespace isotrace
