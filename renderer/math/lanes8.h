#pragma once
// Eight 32-bit lanes (GCC/clang vector extensions: two SSE2 registers on baseline x86-64, one AVX register in an
// AVX2 clone). Arithmetic and comparisons act per lane and round as the scalar operations do (IEEE, no fused
// multiply-add on these targets), so code written lane by lane gives the scalar code's bits. A comparison gives
// a mask: all bits set (-1) where true.
#include <cmath>
#include <cstdint>
#include <cstring>

// Passing a 32-byte vector to a function differs with and without AVX: the compilers warn at every call of the
// helpers below (-Wpsabi) though all of it is inlined and the library is built for one target. Silenced for the
// files that use these lanes.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace isotrace {

using Float8 = float __attribute__((vector_size(32)));
using Int8 = std::int32_t __attribute__((vector_size(32)));
using Uint8 = std::uint32_t __attribute__((vector_size(32)));

inline constexpr int kLanes8 = 8;

inline Float8 splat8(float v) { return Float8{v, v, v, v, v, v, v, v}; }
inline Int8 splat8(std::int32_t v) { return Int8{v, v, v, v, v, v, v, v}; }

// mask ? a : b, per lane; the scalar form too, so that code written once for float and Float8 reads the same.
inline float select(bool mask, float a, float b) { return mask ? a : b; }
inline Float8 select(Int8 mask, Float8 a, Float8 b) { return (Float8)((mask & (Int8)a) | (~mask & (Int8)b)); }
inline Int8 select(Int8 mask, Int8 a, Int8 b) { return (mask & a) | (~mask & b); }

using Float8Half = float __attribute__((vector_size(16)));

inline Float8Half low_half(Float8 v) { return Float8Half{v[0], v[1], v[2], v[3]}; }
inline Float8Half high_half(Float8 v) { return Float8Half{v[4], v[5], v[6], v[7]}; }
inline Float8 join_halves(Float8Half lo, Float8Half hi) {
    return Float8{lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]};
}

// One bit per lane of a mask, lane 0 lowest (movmskps, on each half without AVX: the same in GCC and clang).
inline unsigned lane_bits(Int8 mask) {
    const Float8 bits = (Float8)mask;
#ifdef __AVX__
    return unsigned(__builtin_ia32_movmskps256(bits));
#else
    return unsigned(__builtin_ia32_movmskps(low_half(bits))) | unsigned(__builtin_ia32_movmskps(high_half(bits))) << 4;
#endif
}
inline bool any(Int8 mask) { return lane_bits(mask) != 0; }

// The correctly rounded square root per lane, as std::sqrt gives it.
inline Float8 sqrt(Float8 v) {
#ifdef __AVX__
    return __builtin_ia32_sqrtps256(v);
#else
    return join_halves(__builtin_ia32_sqrtps(low_half(v)), __builtin_ia32_sqrtps(high_half(v)));
#endif
}
inline float abs(float v) { return std::abs(v); }
inline Float8 abs(Float8 v) { return (Float8)((Int8)v & splat8(0x7fffffff)); }
// std::max(a, b) and std::min(a, b) per lane, NaN included: (a < b) ? b : a and (b < a) ? b : a.
inline Float8 max(Float8 a, Float8 b) { return select(a < b, b, a); }
inline Float8 min(Float8 a, Float8 b) { return select(b < a, b, a); }
// std::copysign(1, v) per lane.
inline Float8 sign_of(Float8 v) { return (Float8)(((Int8)v & splat8(std::int32_t(0x80000000u))) | (Int8)splat8(1.0f)); }

// Lanes to and from arrays (Embree's SoA packets, per-lane scalar work).
inline Float8 load8(const float* p) {
    Float8 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline Int8 load8(const std::int32_t* p) {
    Int8 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline void store8(float* p, Float8 v) { std::memcpy(p, &v, sizeof v); }
inline void store8(std::int32_t* p, Int8 v) { std::memcpy(p, &v, sizeof v); }

}  // namespace isotrace
