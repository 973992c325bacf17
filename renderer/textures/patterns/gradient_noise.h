#pragma once
// Gradient noise (Perlin 2002, "Improving Noise"): a smooth random field with a pseudo-random gradient at each
// integer lattice point, where the field is 0.
#include <cstdint>

#include "renderer/math/vec3.h"

namespace isotrace {

// The largest |value| the unscaled sum of a cell's corners reaches (every corner's gradient chosen to point at the
// point, maximised over the cell): gradient_noise divides by it. noise_basis_test checks that the scaled field
// reaches neither beyond ±1 nor far short of it.
inline constexpr float kGradientNoiseUnscaledExtreme = 1.03636f;  // 1.0363539, rounded up

// In [-1, 1] (scaled so that the bound is the field's true extreme), 0 at integer lattice points, C2-continuous.
// The seed selects an independent field. Not band-limited: its detail is about one lattice cell wide.
float gradient_noise(const Vec3f& p, std::uint32_t seed);
// Its gradient, from the formula's derivative (not from differences of the float values).
Vec3f gradient_noise_gradient(const Vec3f& p, std::uint32_t seed);

// The dot product of (x, y, z) with the gradient that a lattice hash selects: one of Perlin's twelve cube-edge
// directions (1, 1, 0), … (four of them twice, so that four hash bits pick one without a division). Inline: simplex
// noise calls it at every corner too.
inline float lattice_gradient_dot(std::uint32_t hash, float x, float y, float z) {
    const std::uint32_t h = hash >> 28;  // the best-mixed bits of mix32
    const float u = h < 8 ? x : y;
    const float v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
    return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

// The gradients at the eight corners of lattice cell `cell` under the lattice seed `root` (lattice_seed), corner
// (a, b, c) at index a + 2b + 4c, each as its three components (0 or ±1).
struct CellGradients {
    float g[8][3];
};
CellGradients cell_gradients(std::uint32_t root, const std::int32_t (&cell)[3]);

}  // namespace isotrace
