#pragma once
// 2^y and log2(x) by short series, for the superellipsoid's powers of fractional exponents, x^p = 2^(p·log2 x): a
// general pow works in extra precision to round correctly, where the gauge needs a few ulps. log2 x to within an
// ulp or two of its size, 2^y to within two ulps plus ln 2·|y|·2⁻⁵³ from y's own rounding (tested through
// NormExponent's powers and roots).
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace isotrace {

// log2 x for a normal, positive, finite x: x = 2^e·m with m ∈ [√½, √2], ln m = 2·atanh(z), z = (m − 1)/(m + 1),
// |z| ≤ 0.172, whose odd series in z reaches the rounding at z²¹.
inline double log2_of(double x) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    int e = int(bits >> 52) - 1023;
    double m = std::bit_cast<double>((bits & 0x000fffffffffffffull) | 0x3ff0000000000000ull);
    if (m > 1.4142135623730951) m *= 0.5, ++e;
    const double z = (m - 1) / (m + 1), w = z * z;
    constexpr double kSeries[] = {1.0 / 3, 1.0 / 5, 1.0 / 7, 1.0 / 9, 1.0 / 11, 1.0 / 13, 1.0 / 15, 1.0 / 17, 1.0 / 19, 1.0 / 21};
    double tail = kSeries[9];
    for (int k = 8; k >= 0; --k) tail = tail * w + kSeries[k];
    return e + (2 * z + 2 * z * (w * tail)) * std::numbers::log2e;
}

// 2^y for y ≤ 1023, 0 below 2⁻¹⁰²⁰ (nothing the gauge adds to 1 notices): 2^n·e^g with n the nearest whole number and
// g = (y − n)·ln 2 ∈ [−0.35, 0.35], whose Taylor series reaches the rounding at g¹³.
inline double exp2_of(double y) {
    if (!(y >= -1020)) return 0;
    // y rounded to the nearest whole number by adding and taking away 1.5·2⁵² (where doubles are whole numbers),
    // which leaves that number in the low bits: std::nearbyint is a call without SSE4.1.
    constexpr double kRounder = 0x1.8p52;
    const double shifted = y + kRounder, n = shifted - kRounder, g = (y - n) * std::numbers::ln2;
    const int whole = int(std::uint32_t(std::bit_cast<std::uint64_t>(shifted)));
    constexpr double kTaylor[] = {1, 1, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720, 1.0 / 5040, 1.0 / 40320,
                                  1.0 / 362880, 1.0 / 3628800, 1.0 / 39916800, 1.0 / 479001600, 1.0 / 6227020800.0};
    double sum = kTaylor[13];
    for (int k = 12; k >= 0; --k) sum = sum * g + kTaylor[k];
    return sum * std::bit_cast<double>(std::uint64_t(whole + 1023) << 52);
}

}  // namespace isotrace
