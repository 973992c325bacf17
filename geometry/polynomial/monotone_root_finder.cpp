#include "geometry/polynomial/monotone_root_finder.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/polynomial/bracketed_root.h"
#include "geometry/polynomial/quadratic_roots.h"

namespace isotrace {
namespace {

struct Sample {
    double t, value;
    bool near_zero;
};

// Evaluates p, deciding whether the value is within rounding of zero. `cheap_bound` bounds the rounding error
// anywhere on the interval, so the exact bound (a second Horner pass) is only needed for values below it.
Sample sample(const Polynomial& p, double t, double cheap_bound) {
    const double value = p.evaluate(t);
    return {t, value, std::abs(value) <= cheap_bound && std::abs(value) <= p.evaluation_error_bound(t)};
}

double interval_error_bound(const Polynomial& p, double a, double b) {
    return p.evaluation_error_bound(std::max(std::abs(a), std::abs(b)));
}

// The roots of a quadratic derivative strictly inside (a, b), by the cancellation-free formula. They only split
// the interval, so a double root that rounding turns into none is harmless: p is monotone across it anyway.
PolynomialRoots quadratic_roots_inside(const Polynomial& quadratic, double a, double b,
                                       const RootTolerance& tolerance) {
    PolynomialRoots roots;
    const QuadraticRoots solved = quadratic_roots(quadratic[2], quadratic[1], quadratic[0]);
    for (int i = 0; i < solved.count; ++i)
        if (solved.roots[i] > a && solved.roots[i] < b) roots.add({solved.roots[i]}, tolerance);
    return roots;
}

// Roots of p in [a, b], given the roots of p' in [a, b] in ascending order: between consecutive critical points
// p is monotone. Stops after the first root when only_first is set.
PolynomialRoots roots_between_critical_points(const Polynomial& p, double a, double b,
                                              const PolynomialRoots& critical_points, const RootTolerance& tolerance,
                                              bool only_first, RootFinderWork* work) {
    PolynomialRoots roots;
    const double cheap_bound = interval_error_bound(p, a, b);
    Sample previous = sample(p, a, cheap_bound);
    if (previous.near_zero) {
        roots.add({a}, tolerance);
        if (only_first) return roots;
    }
    for (int i = 0; i <= critical_points.size(); ++i) {
        const bool at_critical_point = i < critical_points.size();
        const Sample current = sample(p, at_critical_point ? critical_points[i].t : b, cheap_bound);
        if (!previous.near_zero && !current.near_zero && (previous.value < 0) != (current.value < 0)) {
            roots.add({refine_bracketed_root(p, previous.t, current.t, previous.value, current.value, tolerance, work)},
                      tolerance);
            if (only_first) return roots;
        }
        if (current.near_zero) {
            roots.add({current.t, at_critical_point}, tolerance);
            if (only_first) return roots;
        }
        previous = current;
    }
    return roots;
}

PolynomialRoots find_roots(const Polynomial& input, double a, double b, const RootTolerance& tolerance,
                           bool only_first, RootFinderWork* work) {
    const Polynomial p = input.without_negligible_leading_terms(a, b);
    const int degree = p.degree();
    if (degree == 0) return {};
    // derivatives[k] is the k-th derivative; the (degree−1)-th is linear and has no critical points.
    std::array<Polynomial, kMaxPolynomialDegree> derivatives;
    derivatives[0] = p;
    for (int k = 1; k < degree; ++k) derivatives[k] = derivatives[k - 1].derivative();
    // Levels from the quadratic derivative down: the linear one is skipped, the quadratic one solved directly.
    PolynomialRoots critical_points;
    int k = degree - 1;
    if (degree >= 3) {
        critical_points = quadratic_roots_inside(derivatives[degree - 2], a, b, tolerance);
        k = degree - 3;
    }
    for (; k > 0; --k)
        critical_points = roots_between_critical_points(derivatives[k], a, b, critical_points, tolerance, false, work);
    return roots_between_critical_points(p, a, b, critical_points, tolerance, only_first, work);
}

}  // namespace

std::optional<PolynomialRoot> first_root(const Polynomial& p, double a, double b, const RootTolerance& tolerance,
                                         RootFinderWork* work) {
    const PolynomialRoots roots = find_roots(p, a, b, tolerance, true, work);
    if (roots.empty()) return std::nullopt;
    return roots[0];
}

PolynomialRoots all_roots(const Polynomial& p, double a, double b, const RootTolerance& tolerance,
                          RootFinderWork* work) {
    return find_roots(p, a, b, tolerance, false, work);
}

}  // namespace isotrace
