#pragma once
// False-colour error maps: per-pixel errors through a magma-like colour map (black-purple for no error, through
// red and orange, to pale yellow for the largest), as 8-bit sRGB-encoded RGB ready for a PNG.
#include <array>
#include <cstdint>
#include <vector>

namespace isotrace {

// The colour of t in [0, 1] (clamped; NaN counts as 1): piecewise linear between nine anchors read off
// matplotlib's magma map at t = 0, 1/8, ..., 1.
std::array<std::uint8_t, 3> magma_like(double t);

// Each value divided by `full_scale` (> 0), coloured; three bytes per value.
std::vector<std::uint8_t> false_colour(const std::vector<float>& values, double full_scale);

}  // namespace isotrace
