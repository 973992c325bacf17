#pragma once
// Thin tubes along boundary curves, to draw a patch's curves over it as in the paper's Figs. 10–11. Each curve
// becomes a sweep (geometry/sweep) of circular key sections along it, oriented by parallel transport, and is
// tessellated by the sweep layer.
#include <vector>

#include "geometry/curves/space_curve.h"
#include "geometry/mesh/triangle_mesh_data.h"
#include "geometry/sweep/sweep_tessellation.h"

namespace isotrace {

// Each tube's tessellation.
inline constexpr SweepTessellation kBoundaryTube{.theta_steps = 16, .t_steps = 96};

// Throws std::invalid_argument for a radius that is not > 0.
TriangleMeshData boundary_tubes(const std::vector<const SpaceCurve*>& curves, double radius);

}  // namespace isotrace
