#pragma once
// Four doubles side by side (GCC/clang vector extensions: two SSE2 registers on baseline x86-64, one AVX register
// in an AVX build). Arithmetic and comparisons act per lane and round as the scalar operations do (IEEE, no fused
// multiply-add on these targets), so code written lane by lane gives the scalar code's bits. A comparison gives a
// mask: all bits set where true.
#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__AVX__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

// Passing a 32-byte vector to a function differs with and without AVX: the compilers warn at every call of the
// helpers below (-Wpsabi) though all of it is inlined and each build is for one target.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace isotrace {

using Double4 = double __attribute__((vector_size(32)));
using Mask4 = decltype(Double4{} < Double4{});  // the comparisons' own type (long long lanes)

inline Double4 load4(const double* p) {
    Double4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline void store4(double* p, Double4 v) { std::memcpy(p, &v, sizeof v); }

// mask ? a : b per lane.
inline Double4 select(Mask4 mask, Double4 a, Double4 b) { return (Double4)((mask & (Mask4)a) | (~mask & (Mask4)b)); }
// |v| per lane (the sign bit cleared, as std::abs does).
inline Double4 abs4(Double4 v) { return (Double4)((Mask4)v & std::int64_t(0x7fffffffffffffff)); }
// a < b ? a : b and a > b ? a : b per lane (minpd / maxpd).
inline Double4 min4(Double4 a, Double4 b) { return select(a < b, a, b); }
inline Double4 max4(Double4 a, Double4 b) { return select(a > b, a, b); }

// Bit k set when lane k of the mask is.
inline unsigned mask_bits(Mask4 mask) {
#if defined(__AVX__)
    __m256d all;
    std::memcpy(&all, &mask, sizeof all);
    return unsigned(_mm256_movemask_pd(all));
#elif defined(__SSE2__)
    __m128d low, high;
    std::memcpy(&low, &mask, sizeof low);
    std::memcpy(&high, reinterpret_cast<const char*>(&mask) + sizeof low, sizeof high);
    return unsigned(_mm_movemask_pd(low)) | unsigned(_mm_movemask_pd(high)) << 2;
#else
    return (mask[0] ? 1u : 0u) | (mask[1] ? 2u : 0u) | (mask[2] ? 4u : 0u) | (mask[3] ? 8u : 0u);
#endif
}

// The correctly rounded square root per lane, as std::sqrt gives it.
inline Double4 sqrt4(Double4 v) {
#if defined(__SSE2__)
    __m128d low, high;
    std::memcpy(&low, &v, sizeof low);
    std::memcpy(&high, reinterpret_cast<const char*>(&v) + sizeof low, sizeof high);
    low = _mm_sqrt_pd(low);
    high = _mm_sqrt_pd(high);
    Double4 result;
    std::memcpy(&result, &low, sizeof low);
    std::memcpy(reinterpret_cast<char*>(&result) + sizeof low, &high, sizeof high);
    return result;
#else
    return Double4{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
#endif
}

// The sum of the lanes, always in the same order.
inline double lane_sum(Double4 v) { return (v[0] + v[1]) + (v[2] + v[3]); }
// {lane_sum(a), lane_sum(b), lane_sum(c), lane_sum(d)}, the same bits, in four additions of whole vectors.
inline Double4 lane_sums(Double4 a, Double4 b, Double4 c, Double4 d) {
    const Double4 ab = __builtin_shufflevector(a, b, 0, 4, 2, 6) + __builtin_shufflevector(a, b, 1, 5, 3, 7);
    const Double4 cd = __builtin_shufflevector(c, d, 0, 4, 2, 6) + __builtin_shufflevector(c, d, 1, 5, 3, 7);
    return __builtin_shufflevector(ab, cd, 0, 1, 4, 5) + __builtin_shufflevector(ab, cd, 2, 3, 6, 7);
}
// The least lane (NaN-free lanes).
inline double lane_min(Double4 v) {
    const double a = v[0] < v[1] ? v[0] : v[1], b = v[2] < v[3] ? v[2] : v[3];
    return a < b ? a : b;
}

}  // namespace isotrace
