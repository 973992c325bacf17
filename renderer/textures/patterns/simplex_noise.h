#pragma once
// Simplex noise (Perlin 2001; as written in Gustavson, "Simplex noise demystified"): gradient noise summed over the
// four corners of the simplex (tetrahedron) holding the point instead of the eight corners of a cube, so it costs
// less and has no axis-aligned artefacts.
#include <cstdint>

#include "renderer/math/vec3.h"

namespace isotrace {

// In [-1, 1] (scaled so that the bound is the field's true extreme), continuous with continuous derivatives. The
// seed selects an independent field. Not band-limited: its detail is about one lattice cell wide.
float simplex_noise(const Vec3f& p, std::uint32_t seed);

}  // namespace isotrace
