#pragma once
// A p-norm's exponent p = 2/ε and the powers and roots the superellipsoid's gauge takes with it: r^p of a share
// r ∈ [0, 1], and the root s^(1/p) of 1 + r^p ∈ [1, 2]. Those are the gauge's hottest calls, and a general pow
// (which works in extra precision to round correctly) costs several times what they need, so small whole
// exponents (2/ε for the common ε = 1, 0.5, 0.2, 0.1, ...) take powers by repeated squaring, unrolled for each
// exponent, and roots by one Halley step on x^p = s from a polynomial first guess; fractional ones keep pow, whose
// short latency a series of the same accuracy did not match (docs/decisions.md).
#include <array>
#include <cmath>

namespace isotrace {

struct NormExponent {
    double p = 2;
    int whole = 2;  // p when it is a whole number up to 64, else 0
    double inverse = 0.5;
    double (*whole_power)(double) = nullptr;  // x^p by repeated squaring, for whole p
    // For whole p without a closed-form root: s^(1/p) over s ∈ [1, 2] as a polynomial in 2s − 3 (interpolation at
    // Chebyshev nodes, within 2·10⁻⁶ for every whole p ≥ 3), the first guess of root().
    std::array<double, 6> root_guess{};

    static NormExponent of_epsilon(double epsilon);

    // r^p for r in [0, 1].
    double unit_power(double r) const {
        if (whole == 2) return r * r;  // without the call: round cross-sections are the rule
        if (whole > 0) return whole_power(r);
        return r == 0 ? 0 : std::pow(r, p);  // on coordinate planes: pow's exact answer without the call
    }
    // s^(1/p) for s in [1, 2], within an ulp (the error against a long double pow is tested for every whole p).
    double root(double s) const {
        if (whole < 3 || whole == 4) return any_root(s);
        // Halley's step on f(x) = x^p − s, x − 2f·f′/(2f′² − f·f″), written as a correction of x: cubic convergence
        // takes the guess's error below the rounding, and the correction carries the power's rounding only
        // divided by p.
        // The guess in pairs of terms (Estrin's scheme): three short chains rather than one of five steps.
        const double t = 2 * s - 3, t2 = t * t;
        const auto& c = root_guess;
        static_assert(std::tuple_size_v<decltype(root_guess)> == 6);
        const double x = (c[0] + c[1] * t) + t2 * ((c[2] + c[3] * t) + t2 * (c[4] + c[5] * t));
        const double power = whole_power(x);
        return x + x * (2 * (s - power) / ((p + 1) * power + (p - 1) * s));
    }
    // s^(1/p) for any s ≥ 0, in closed form where there is one.
    double any_root(double s) const {
        switch (whole) {
            case 1: return s;
            case 2: return std::sqrt(s);
            case 4: return std::sqrt(std::sqrt(s));
            // 1 + r^p rounds to 1 on coordinate planes and wherever r^p < 2⁻⁵³: pow's exact answer without the call.
            default: return s == 1 ? 1 : std::pow(s, inverse);
        }
    }
};

}  // namespace isotrace
