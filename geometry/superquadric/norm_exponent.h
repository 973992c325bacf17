#pragma once
// A p-norm's exponent p = 2/ε and the powers and roots the superellipsoid's gauge takes with it: r^p of a share
// r ∈ [0, 1], and the root s^(1/p) of 1 + r^p ∈ [1, 2]. Those are the gauge's hottest calls, and a general pow
// (which works in extra precision to round correctly) costs several times what they need, so small whole
// exponents (2/ε for the common ε = 1, 0.5, 0.2, 0.1, ...) take powers by repeated squaring, unrolled for each
// exponent, and every exponent without a closed-form root takes its roots by a polynomial of degree 17 (a short
// chain of dependent operations, where a root is on the gauge's critical path); fractional powers keep pow, whose
// short latency a series of the same accuracy did not match (docs/decisions.md).
#include <array>
#include <cmath>

namespace isotrace {

struct NormExponent {
    double p = 2;
    int whole = 2;  // p when it is a whole number up to 64, else 0
    double inverse = 0.5;
    double (*whole_power)(double) = nullptr;  // x^p by repeated squaring, for whole p
    // For p without a closed-form root (all but 1, 2 and 4): s^(1/p) over s ∈ [1, 2] as a polynomial in 2s − 3
    // (interpolation at Chebyshev nodes, within 4 ulps for every whole p up to 64 and fractional ones tested),
    // root() itself.
    std::array<double, 18> root_polynomial{};

    static NormExponent of_epsilon(double epsilon);

    // r^p for r in [0, 1].
    double unit_power(double r) const {
        if (whole == 2) return r * r;  // without the call: round cross-sections are the rule
        if (whole > 0) return whole_power(r);
        return r == 0 ? 0 : std::pow(r, p);  // on coordinate planes: pow's exact answer without the call
    }
    // s^(1/p) for s in [1, 2], within a few ulps (the error against a long double pow is tested).
    double root(double s) const {
        if (has_closed_root()) return any_root(s);
        // Estrin's scheme: pairs of terms, then pairs of pairs in t², ..., five short chains rather than one long one
        // (a root is on the gauge's critical path).
        const auto& c = root_polynomial;
        static_assert(std::tuple_size_v<decltype(root_polynomial)> == 18);
        const double t = 2 * s - 3, t2 = t * t, t4 = t2 * t2, t8 = t4 * t4, t16 = t8 * t8;
        const double a0 = c[0] + c[1] * t, a1 = c[2] + c[3] * t, a2 = c[4] + c[5] * t, a3 = c[6] + c[7] * t,
                     a4 = c[8] + c[9] * t, a5 = c[10] + c[11] * t, a6 = c[12] + c[13] * t, a7 = c[14] + c[15] * t,
                     a8 = c[16] + c[17] * t;
        const double b0 = a0 + a1 * t2, b1 = a2 + a3 * t2, b2 = a4 + a5 * t2, b3 = a6 + a7 * t2;
        const double d0 = b0 + b1 * t4, d1 = b2 + b3 * t4;
        return (d0 + d1 * t8) + a8 * t16;
    }
    bool has_closed_root() const { return whole == 1 || whole == 2 || whole == 4; }
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
