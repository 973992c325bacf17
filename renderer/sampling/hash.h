#pragma once
// Integer hashing for deterministic sampling: every random number in the renderer is a hash of
// (pixel, sample index, dimension, seed), never the state of a generator.
#include <concepts>
#include <cstdint>

#include "renderer/math/lanes4.h"

namespace isotrace {

// MurmurHash3's 32-bit finaliser: full avalanche, a bijection on uint32_t (per lane for a Uint4).
template <Uint32Bits Bits>
constexpr Bits mix32(Bits h) {
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h;
}

// SplitMix64's finaliser (Stafford's "Mix13"): full avalanche, a bijection on uint64_t.
constexpr uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// Continues an order-sensitive hash with more integers: each value is mixed on its own before it meets the
// state, so small neighbouring inputs (pixel 3 vs 4, dimension 0 vs 1) give unrelated results.
// hash_extend(hash_combine(a, b), c) == hash_combine(a, b, c): a shared prefix is hashed once.
template <std::integral... Values>
constexpr uint64_t hash_extend(uint64_t state, Values... values) {
    constexpr uint64_t golden_gamma = 0x9e3779b97f4a7c15ull;  // keeps value 0 from being a fixed point of mix64
    ((state = mix64(state ^ mix64(static_cast<uint64_t>(values) + golden_gamma))), ...);
    return state;
}

template <std::integral... Values>
constexpr uint64_t hash_combine(Values... values) {
    return hash_extend(0, values...);
}

// Top 24 bits as a float in [0,1): every result is exactly representable, so it can never round up to 1.
constexpr float uint_to_unit_float(uint32_t bits) {
    return static_cast<float>(bits >> 8) * 0x1p-24f;
}

}  // namespace isotrace
