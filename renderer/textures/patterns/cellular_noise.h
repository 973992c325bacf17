#pragma once
// Cellular noise (Worley 1996, "A Cellular Texture Basis Function"): distances from a point to the nearest feature
// points of a random point set, one feature point per unit lattice cell.
#include <array>
#include <cstdint>

#include "renderer/math/vec3.h"

namespace isotrace {

enum class CellularOutput {
    F1,         // distance to the nearest feature point: in [0, √3], 0 at a feature point
    F2,         // distance to the second nearest: in [F1, √6]
    F2MinusF1,  // 0 on the borders between cells
    CellValue,  // a random value in [0, 1) per feature point, constant over its Voronoi cell
};

// Cell (x, y, z)'s feature point lies at the cell's centre moved by jitter × (a random offset in [−½, ½)³): jitter
// 0 is a regular grid, 1 fills each cell (clamped to [0, 1], NaN to 0). The seed selects an independent point set.
// The search visits the 27 cells around p's cell, a bound on the work; with jitter above about ½ a nearer feature
// point two cells away is possible and then missed, which leaves rare small creases, as in most renderers.
//
// The footprint (the width of a pixel at p, in cells; 0 = a point sample) fades the output to its mean over space
// between a footprint of ½ and 1 cell, where cells become smaller than a pixel and would alias; the search is
// skipped from 1 cell on.
float cellular(const Vec3f& p, std::uint32_t seed, float jitter, CellularOutput output, float footprint);

// Cell (x, y, z)'s feature point, in the coordinates of p.
Vec3f cellular_feature_point(std::array<std::int32_t, 3> cell, std::uint32_t seed, float jitter);

// Cell (x, y, z)'s CellValue.
float cellular_cell_value(std::array<std::int32_t, 3> cell, std::uint32_t seed);

// The mean over space of an output at a jitter, the value that a large footprint gives.
float cellular_mean(CellularOutput output, float jitter);

}  // namespace isotrace
