#pragma once
// Hash-based nested uniform (Owen) scrambling in base 2 (Burley 2020, "Practical Hash-based Owen
// Scrambling", JCGT 9(4)). Used both to scramble Sobol' values and to shuffle sample indices.
#include <cstdint>

#include "renderer/math/lanes4.h"

namespace isotrace {

template <Uint32Bits Bits>
constexpr Bits reverse_bits(Bits v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
    return (v >> 16) | (v << 16);
}

// Laine-Karras style permutation with Burley's constants. Addition and `x ^= x * even` only carry
// information from lower to higher bits, so output bit k is input bit k flipped by a function of the seed
// and bits below k: exactly the structure of an Owen scramble when applied to bit-reversed values.
template <Uint32Bits Bits>
constexpr Bits laine_karras_permutation(Bits x, Bits seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Owen scramble of a 0.32 fixed-point value: each bit is flipped depending only on the seed and the more
// significant bits, so every dyadic interval maps onto a dyadic interval of the same size (stratification
// is preserved). `seed` should be well mixed (e.g. from hash_combine).
constexpr uint32_t nested_uniform_scramble(uint32_t x, uint32_t seed) {
    return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

// The same scramble of x given as reverse_bits(x), as sobol_sample_bit_reversed produces it: one reversal
// fewer on the sampler's hot path.
template <Uint32Bits Bits>
constexpr Bits nested_uniform_scramble_of_reversed(Bits reversed_x, Bits seed) {
    return reverse_bits(laine_karras_permutation(reversed_x, seed));
}

}  // namespace isotrace
