#pragma once
// Grid lines at integer coordinates.
#include <array>

#include "renderer/math/vec3.h"

namespace isotrace {

// 1 within line_width/2 of an integer (bounds included) in any coordinate (in three dimensions the lines are slabs around the planes
// x, y or z ∈ ℤ, which draw lines on any surface crossing them), else 0. line_width is the lines' width in cells,
// clamped to [0, 1] (NaN to 0). A footprint w > 0 (the width of a pixel at p) gives the exact mean over the cube of
// side w centred on p (an analytic box filter, axis by axis), which tends to the grid's coverage
// 1 − (1 − line_width)³ as w grows past a cell.
float grid(const Vec3f& p, float line_width, float footprint);

// The same in two dimensions: lines at integer u or v, tending to 1 − (1 − line_width)² for wide footprints.
float grid_2d(std::array<float, 2> uv, float line_width, float footprint);

}  // namespace isotrace
