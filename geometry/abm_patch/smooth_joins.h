#pragma once
// Smooth joins between attribute-based patches. The paper's blend uses the boundary curves only, so two patches
// sharing a curve meet with positional continuity and generally a crease. Here each curve shared by exactly two
// patches gets a common normal N(t) — the mean of the two patches' planes along it (each spanned by the tangent and
// the secant to the patch's centre), shifted toward the ends to the mean of the two patches' corner planes (the
// planes of the curves meeting there) — and each of the two sides a cross-boundary tangent built from it
// (cross_tangent.h), of a reach of the patch's own: the secant to its centre projected onto the plane normal to N.
// Both patches then have the tangent plane normal to N along the whole curve (with p > 1), so their normals agree.
//
// Curves used by one patch (an open edge) or by more than two keep the plain attribute. Where three or more curves
// meet at a corner whose tangents do not lie in one plane (the apex of a gem), no surface can be smooth; the
// patches meet there at a point with their own tangent planes.
#include <vector>

#include "geometry/abm_patch/abm_patch.h"

namespace isotrace {

// Samples of the common normal per curve (interpolated by a cubic B-spline in between): at least this many, more
// for curves with many control points.
inline constexpr int kRibbonSamples = 32;

// The patches with cross-boundary tangents on every side whose curve exactly one other patch shares. Throws
// std::invalid_argument for such a patch with a weight exponent p ≤ 1 (with p = 1 the other sides pull the surface
// off its tangent plane to first order).
std::vector<AbmPatch> with_smooth_joins(const std::vector<AbmPatch>& patches);

}  // namespace isotrace
