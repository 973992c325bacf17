#pragma once
// Guaranteed bounds of gradient noise (renderer/textures/patterns/gradient_noise) and of its gradient over a small
// box of the noise's own coordinates: the noise's formula (corner gradients · offsets, blended by the quintic
// fade) evaluated in interval arithmetic in each lattice cell the box meets, and the hull taken. Far tighter than
// a Lipschitz bound: the values of a box a tenth of a cell wide come within a few times its width × the local
// slope, not the steepest slope anywhere.
#include <cstdint>
#include <optional>

#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct NoiseBoxBounds {
    Interval value;         // every value of the exact (real-number) noise over the box
    IntervalBox gradient;   // every partial derivative over the box
};

// The most lattice cells a box may meet to be bounded cell by cell (the cost grows with them).
constexpr int kMaxBoundedNoiseCells = 8;

// Bounds over `box` (the noise's coordinates, finite and within ±2^22), or nothing when the box meets more than
// kMaxBoundedNoiseCells cells or lies outside that range. Computed in double: the caller allows for the float
// evaluation of the texture's noise.
std::optional<NoiseBoxBounds> gradient_noise_bounds(const IntervalBox& box, std::uint32_t seed);
// The value's bound at a point (gradient_noise_bounds of the point box, bit for bit), for less: no gradient.
std::optional<Interval> gradient_noise_value_at(const Vec3d& q, std::uint32_t seed);

}  // namespace isotrace
