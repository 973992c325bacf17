#pragma once
// A p-norm's exponent p = 2/ε and the powers and roots the superellipsoid's gauge takes with it: r^p of a share
// r ∈ [0, 1], and the root s^(1/p) of 1 + r^p ∈ [1, 2]. Those are the gauge's hottest calls, and a general pow
// (which works in extra precision to round correctly) costs several times what they need, so small whole
// exponents (2/ε for the common ε = 1, 0.5, 0.2, 0.1, ...) take powers by repeated squaring, unrolled for each
// exponent, and every exponent without a closed-form root takes its roots by a polynomial of degree 17 (a short
// chain of dependent operations, where a root is on the gauge's critical path). Fractional powers up to p = 16 split
// r = 2^−k·m with m ∈ [1, 2): m^p by a polynomial of the same degree on each half of [1, 2), 2^(−kp) from a table of
// 64 octaves; smaller shares, whose powers hardly count, and larger exponents keep pow (docs/decisions.md).
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

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
    // For fractional p up to kMostTabulated: m^p over each half of [1, 2) as a polynomial in s ∈ [0, 1), and the
    // powers 2^(−kp) of the octaves k = 0 to 63.
    static constexpr double kMostTabulated = 16;
    static constexpr int kOctaves = 64;
    bool tabulated = false;
    std::array<std::array<double, 18>, 2> mantissa_power_polynomials{};
    std::array<double, kOctaves> octave_powers{};

    static NormExponent of_epsilon(double epsilon);

    // r^p for r in [0, 1], within a few ulps (tested against a long double pow).
    double unit_power(double r) const {
        if (whole == 2) return r * r;  // without the call: round cross-sections are the rule
        if (whole > 0) return whole_power(r);
        if (tabulated && r >= 0x1p-63) {
            // r = 2^−k·m: the exponent field gives k, the mantissa's leading bit the half of [1, 2) m lies in, and
            // s = 2m − 2 or 2m − 3 (exact) the polynomial's argument.
            const std::uint64_t bits = std::bit_cast<std::uint64_t>(r);
            const int octave = 1023 - int(bits >> 52), half = int(bits >> 51) & 1;
            const double m = std::bit_cast<double>((bits & 0x000f'ffff'ffff'ffffull) | 0x3ff0'0000'0000'0000ull);
            const double power = polynomial(mantissa_power_polynomials[half], 2 * m - (2 + half)) *
                                 octave_powers[octave];
            return r == 1 ? 1 : power;  // 1 exactly: 1 − r^p is a p-ball's edge, 0 at its pole
        }
        return r == 0 ? 0 : std::pow(r, p);  // on coordinate planes: pow's exact answer without the call
    }
    // s^(1/p) for s in [1, 2], within a few ulps (the error against a long double pow is tested).
    double root(double s) const {
        if (has_closed_root()) return any_root(s);
        return polynomial(root_polynomial, 2 * s - 3);
    }
    bool has_closed_root() const { return whole == 1 || whole == 2 || whole == 4; }
    // Σ cᵢ·tⁱ by Estrin's scheme: pairs of terms, then pairs of pairs in t², ..., five short chains rather than one
    // long one (powers and roots are on the gauge's critical path). Written out: as a loop the compiler kept the loop.
    static double polynomial(const std::array<double, 18>& c, double t) {
        const double t2 = t * t, t4 = t2 * t2, t8 = t4 * t4, t16 = t8 * t8;
        const double a0 = c[0] + c[1] * t, a1 = c[2] + c[3] * t, a2 = c[4] + c[5] * t, a3 = c[6] + c[7] * t,
                     a4 = c[8] + c[9] * t, a5 = c[10] + c[11] * t, a6 = c[12] + c[13] * t, a7 = c[14] + c[15] * t,
                     a8 = c[16] + c[17] * t;
        const double b0 = a0 + a1 * t2, b1 = a2 + a3 * t2, b2 = a4 + a5 * t2, b3 = a6 + a7 * t2;
        const double d0 = b0 + b1 * t4, d1 = b2 + b3 * t4;
        return (d0 + d1 * t8) + a8 * t16;
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
