#pragma once
// The real roots of a·s² + b·s + c, without the cancellation of the school formula: the larger root comes from
// q = −(b + sign(b)·√D)/2 as q/a and the smaller one as c/q (Numerical Recipes §5.6), so both keep full relative
// precision. The one quadratic solver of isotrace: ray–sphere, ray–support, critical points of cubics and the
// metacube region cuts all come here.
#include <cmath>
#include <utility>

namespace isotrace {

struct QuadraticRoots {
    int count = 0;            // 0, 1 (linear, or a double root) or 2
    double roots[2] = {0, 0};  // ascending
};

// Roots of a·s² + b·s + c given its discriminant D = b² − 4ac (a caller with a more accurate D than the
// formula, such as a ray–sphere test, passes its own). a = 0 is the linear case; a = b = 0 has no roots.
inline QuadraticRoots quadratic_roots_with_discriminant(double a, double b, double c, double discriminant) {
    QuadraticRoots result;
    if (a == 0) {
        if (b != 0) result.roots[result.count++] = -c / b;
        return result;
    }
    if (discriminant < 0) return result;
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    if (q == 0) {  // b = D = 0: a double root at 0 (c = 0)
        result.count = 1;
        return result;
    }
    double r0 = q / a, r1 = c / q;
    if (r0 > r1) std::swap(r0, r1);
    result.roots[0] = r0;
    result.roots[1] = r1;
    result.count = r0 == r1 ? 1 : 2;
    return result;
}

inline QuadraticRoots quadratic_roots(double a, double b, double c) {
    return quadratic_roots_with_discriminant(a, b, c, b * b - 4 * a * c);
}

}  // namespace isotrace
