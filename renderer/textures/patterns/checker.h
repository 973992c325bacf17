#pragma once
// Checkerboards of unit cells: 0 on the cell [0, 1)³ (or [0, 1)²), alternating across every face.
#include <array>

#include "renderer/math/vec3.h"

namespace isotrace {

// In {0, 1} for a point sample (footprint 0): (⌊x⌋ + ⌊y⌋ + ⌊z⌋) mod 2. A footprint w > 0 (the width of a pixel at
// p) gives the exact mean over the cube of side w centred on p (an analytic box filter: the product of the three
// axes' filtered square waves), which tends to 0.5 as w grows past a cell.
float checker(const Vec3f& p, float footprint);

// The same in two dimensions: (⌊u⌋ + ⌊v⌋) mod 2, box-filtered over the square of side footprint.
float checker_2d(std::array<float, 2> uv, float footprint);

}  // namespace isotrace
