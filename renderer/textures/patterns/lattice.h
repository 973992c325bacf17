#pragma once
// The integer lattice the noise and cellular patterns are built on: where a coordinate falls in it, and a hash of
// each lattice cell under a seed (in place of Perlin's permutation table, so every seed is an independent field).
#include <cstdint>

#include "renderer/sampling/hash.h"

namespace isotrace {

// A coordinate split into its lattice cell and the offset inside it (in [0, 1]). Coordinates are clamped to ±2^29,
// where floats are integers already, so a cell (even in simplex noise's skewed lattice) and its neighbours always
// fit an int32; NaN reads as 0, so a bad coordinate gives a value of the pattern, never NaN or undefined behaviour.
struct LatticeCoordinate {
    std::int32_t cell;
    float offset;
};

constexpr float kLatticeLimit = 0x1p29f;

// x clamped to ±2^29, NaN to 0 (every comparison with NaN is false).
constexpr float lattice_clamp(float x) {
    return x >= -kLatticeLimit ? (x <= kLatticeLimit ? x : kLatticeLimit) : (x < -kLatticeLimit ? -kLatticeLimit : 0.0f);
}

// ⌊x⌋ for |x| ≤ 2^30 (clamped coordinates, and simplex noise's skewed ones), without a call to floorf.
constexpr std::int32_t lattice_floor(float x) {
    const auto truncated = static_cast<std::int32_t>(x);
    return x < static_cast<float>(truncated) ? truncated - 1 : truncated;
}

constexpr LatticeCoordinate lattice_coordinate(float x) {
    const float clamped = lattice_clamp(x);
    const std::int32_t cell = lattice_floor(clamped);
    return {cell, clamped - static_cast<float>(cell)};
}

// Hashes chain one axis at a time, so the corners of a cell share the hashes of their common prefixes:
// lattice_hash(lattice_hash(lattice_hash(lattice_seed(seed), x), y), z) is the hash of cell (x, y, z).
constexpr std::uint32_t lattice_seed(std::uint32_t seed) {
    return mix32(seed + 0x9e3779b9u);  // the golden-ratio offset keeps seed 0 from hashing to 0
}

constexpr std::uint32_t lattice_hash(std::uint32_t prefix, std::int32_t coordinate) {
    return mix32(prefix ^ static_cast<std::uint32_t>(coordinate));
}

// Independent random numbers from one hash, numbered by `stream` (from 1): the hash mixed again after adding a
// distinct multiple of an odd constant.
constexpr std::uint32_t hash_stream(std::uint32_t hash, std::uint32_t stream) {
    return mix32(hash + stream * 0x9e3779b9u);
}

constexpr std::uint32_t cell_hash(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t seed) {
    return lattice_hash(lattice_hash(lattice_hash(lattice_seed(seed), x), y), z);
}

}  // namespace isotrace
