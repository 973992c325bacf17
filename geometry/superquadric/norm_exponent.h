#pragma once
// A p-norm's exponent p = 2/ε and the powers and roots the superellipsoid's gauge takes with it: r^p of a share
// r ∈ [0, 1], and the root s^(1/p) of 1 + r^p ∈ [1, 2]. Those are the gauge's hottest calls, and a general pow
// (which works in extra precision to round correctly) costs several times what they need, so small whole
// exponents (2/ε for the common ε = 1, 0.5, 0.2, 0.1, ...) take powers by repeated squaring, unrolled for each
// exponent, and every exponent without a closed-form root takes its roots by a polynomial of degree 17 (a short
// chain of dependent operations, where a root is on the gauge's critical path). Fractional powers up to p = 16 split
// r = 2^−k·m with m ∈ [1, 2): m^p by a polynomial of the same degree on each half of [1, 2), 2^(−kp) from a table of
// 64 octaves; smaller shares, whose powers hardly count, and larger exponents keep pow. Where only the norm is wanted
// (a value of the gauge, not its slope), fractional exponents up to p = 8 take ‖(1, r)‖_p = (1 + r^p)^(1/p) for r down
// to 2^−8 from polynomials of its own: half the chain of a power and then a root (docs/decisions.md).
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>

namespace isotrace {

// The polynomials and octave powers of one exponent (NormExponent, below), made once per exponent and shared by
// every NormExponent made for it: a scene's superquadrics share a few exponents, and the tables are most of their size.
struct NormTables {
    // The octaves of the powers' table, and those the norm's polynomials cover: r ∈ [2^−kNormOctaves, 1).
    static constexpr int kOctaves = 64, kNormOctaves = 8;
    static constexpr double kLeastNormShare = 1.0 / (1 << kNormOctaves);
    // For p without a closed-form root (all but 1, 2 and 4): s^(1/p) over s ∈ [1, 2] as a polynomial in 2s − 3
    // (interpolation at Chebyshev nodes, within 4 ulps for every whole p up to 64 and fractional ones tested),
    // root() itself.
    std::array<double, 18> root_polynomial{};
    // For fractional p up to NormExponent::kMostTabulated: m^p over each half of [1, 2) as a polynomial in
    // s ∈ [0, 1), and the powers 2^(−kp) of the octaves k = 0 to 63.
    std::array<std::array<double, 18>, 2> mantissa_power_polynomials{};
    std::array<double, kOctaves> octave_powers{};
    // For fractional p up to NormExponent::kMostNormTabulated: the norm ‖(1, r)‖_p = (1 + r^p)^(1/p) itself for
    // r ∈ [2^−8, 1), by a polynomial of the same degree on each half of each of those eight octaves: one chain of
    // dependent operations on the gauge's critical path where the power and then the root of 1 + r^p take two.
    std::array<std::array<double, 18>, 2 * kNormOctaves> norm_polynomials{};
};

struct NormExponent {
    double p = 2;
    int whole = 2;  // p when it is a whole number up to 64, else 0
    double inverse = 0.5;
    bool norm_tabulated = false;  // the tables hold the norm's own polynomials
    double (*whole_power)(double) = nullptr;  // x^p by repeated squaring, for whole p
    static constexpr double kMostTabulated = 16, kMostNormTabulated = 8;
    bool tabulated = false;  // the tables hold the powers' polynomials and octaves
    // Null where p needs none (p = 1, 2, 4).
    std::shared_ptr<const NormTables> tables{};

    static NormExponent of_epsilon(double epsilon);

    // r^p for r in [0, 1], within a few ulps (tested against a long double pow).
    double unit_power(double r) const {
        if (whole == 2) return r * r;  // without the call: round cross-sections are the rule
        if (whole > 0) return whole_power(r);
        if (tabulated && r >= 0x1p-63) {
            const OctaveSplit at = split(r);
            const double power = polynomial(tables->mantissa_power_polynomials[at.half], at.s) *
                                 tables->octave_powers[at.octave];
            return r == 1 ? 1 : power;  // 1 exactly: 1 − r^p is a p-ball's edge, 0 at its pole
        }
        return r == 0 ? 0 : std::pow(r, p);  // on coordinate planes: pow's exact answer without the call
    }
    // Whether ‖(1, r)‖_p has its own polynomial at r (tabulated_norm).
    bool has_tabulated_norm(double r) const { return norm_tabulated && r >= NormTables::kLeastNormShare && r < 1; }
    // ‖(1, r)‖_p for r where has_tabulated_norm(r), within a few ulps (tested against long double). Out of line: its
    // twenty-odd values would crowd the registers of every p-norm it were inlined into, for all exponents.
    [[gnu::noinline]] double tabulated_norm(double r) const {
        const OctaveSplit at = split(r);  // octave 1 to 8
        return polynomial(tables->norm_polynomials[2 * (at.octave - 1) + at.half], at.s);
    }
    // s^(1/p) for s in [1, 2], within a few ulps (the error against a long double pow is tested).
    double root(double s) const {
        if (has_closed_root()) return any_root(s);
        return polynomial(tables->root_polynomial, 2 * s - 3);
    }
    bool has_closed_root() const { return whole == 1 || whole == 2 || whole == 4; }
    // r = 2^−octave·m with m ∈ [1, 2) for a positive normal r: the exponent field gives the octave, the mantissa's
    // leading bit the half of [1, 2) m lies in, and s = 2m − 2 or 2m − 3 (exact) the argument of that half's polynomial.
    struct OctaveSplit {
        int octave, half;
        double s;
    };
    static OctaveSplit split(double r) {
        const std::uint64_t bits = std::bit_cast<std::uint64_t>(r);
        const int half = int(bits >> 51) & 1;
        const double m = std::bit_cast<double>((bits & 0x000f'ffff'ffff'ffffull) | 0x3ff0'0000'0000'0000ull);
        return {1023 - int(bits >> 52), half, 2 * m - (2 + half)};
    }
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
