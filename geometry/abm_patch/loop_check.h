#pragma once
// Boundary curves of a patch must form a closed loop: each side ends where the next begins.
#include <string>
#include <vector>

#include "geometry/abm_patch/patch_side.h"

namespace isotrace {

inline constexpr int kLoopSamplesPerCurve = 32;

// A point and a distance as the patch messages print them: "(1, 0, 0.5)", "0.0001".
std::string format_point(const Vec3d& p);
std::string format_number(double v);

// Throws std::invalid_argument naming the two curves, their end points and the gap when side i's end and side
// i+1's start (mod N) are farther apart than `tolerance`; when the gap closes with one of them run backwards, the
// message says so.
void check_closed_loop(const std::vector<PatchSide>& sides, double tolerance);

// Throws std::invalid_argument naming two curves that cross or touch when the loop is seen along its mean normal (a
// bow-tie): the patch would fold over onto itself. The loop is sampled as a polyline (kLoopSamplesPerCurve points
// per curve, more for curves with many control points) and projected along its Newell normal, or, where that
// vanishes (a symmetric planar bow-tie), along the normal of the plane its points span.
void check_not_self_crossing(const std::vector<PatchSide>& sides);

// Throws std::invalid_argument for a side whose curve has (nearly) zero length: it cannot bound a patch.
void check_not_degenerate(const std::vector<PatchSide>& sides);

}  // namespace isotrace
