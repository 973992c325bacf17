#pragma once
// kLanes 32-bit lanes (GCC/clang vector extensions), for code that fills and reads Embree's packets of eight rays
// or tests eight candidates at once: two SSE2 registers on baseline x86-64, one AVX register in an AVX2 build.
// Arithmetic and comparisons act per lane and round as the scalar operations do (IEEE, no fused multiply-add on
// these targets), so code written lane by lane gives the scalar code's bits. A comparison gives a mask: all bits
// set (-1) where true.
#include <cmath>
#include <cstdint>
#include <cstring>

// Passing a vector wider than 16 bytes to a function differs with and without AVX: the compilers warn at every
// call of the helpers below (-Wpsabi) though all of it is inlined and each build is for one target. Silenced for
// the files that use these lanes.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace isotrace {

// Eight: sixteen (Embree's 16-wide packets, two AVX registers a value) took 1.2 times as long on the path
// tracer's box (docs/benchmarks.md, "What did not pay").
inline constexpr int kLanes = 8;

using FloatLanes = float __attribute__((vector_size(4 * kLanes)));
using IntLanes = std::int32_t __attribute__((vector_size(4 * kLanes)));

inline FloatLanes splat(float v) { return FloatLanes{} + v; }
inline IntLanes splat(std::int32_t v) { return IntLanes{} + v; }

// mask ? a : b, per lane.
inline FloatLanes select(IntLanes mask, FloatLanes a, FloatLanes b) {
    return (FloatLanes)((mask & (IntLanes)a) | (~mask & (IntLanes)b));
}
inline IntLanes select(IntLanes mask, IntLanes a, IntLanes b) { return (mask & a) | (~mask & b); }

// The lanes in parts the instruction set has registers for (8 with AVX, else 4).
#ifdef __AVX__
using FloatPart = float __attribute__((vector_size(32)));
#else
using FloatPart = float __attribute__((vector_size(16)));
#endif
inline constexpr int kPartLanes = int(sizeof(FloatPart) / sizeof(float));
static_assert(kLanes % kPartLanes == 0, "the lanes must fill whole parts");

// One bit per lane of a mask, lane 0 lowest (movmskps on each part: the same in GCC and clang).
inline unsigned lane_bits(IntLanes mask) {
    unsigned bits = 0;
    for (int first = 0; first < kLanes; first += kPartLanes) {
        FloatPart part;
        std::memcpy(&part, reinterpret_cast<const float*>(&mask) + first, sizeof part);
#ifdef __AVX__
        bits |= unsigned(__builtin_ia32_movmskps256(part)) << first;
#else
        bits |= unsigned(__builtin_ia32_movmskps(part)) << first;
#endif
    }
    return bits;
}

inline float abs(float v) { return std::abs(v); }
inline FloatLanes abs(FloatLanes v) { return (FloatLanes)((IntLanes)v & splat(0x7fffffff)); }
// std::max(a, b) and std::min(a, b) per lane, NaN included: (a < b) ? b : a and (b < a) ? b : a.
inline FloatLanes max(FloatLanes a, FloatLanes b) { return select(a < b, b, a); }
inline FloatLanes min(FloatLanes a, FloatLanes b) { return select(b < a, b, a); }

// Lanes to and from arrays (Embree's SoA packets).
inline FloatLanes load_lanes(const float* p) {
    FloatLanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline IntLanes load_lanes(const std::int32_t* p) {
    IntLanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline void store_lanes(float* p, FloatLanes v) { std::memcpy(p, &v, sizeof v); }
inline void store_lanes(std::int32_t* p, IntLanes v) { std::memcpy(p, &v, sizeof v); }

// The lanes whose bit is set in `bits` (lane 0 the lowest bit) as a mask.
inline IntLanes lanes_of_bits(unsigned bits) {
    return (splat(std::int32_t(bits)) & IntLanes{1, 2, 4, 8, 16, 32, 64, 128}) != 0;
}

}  // namespace isotrace
