#pragma once
// Boundary curves of a patch must form a closed loop: each side ends where the next begins.
#include <vector>

#include "geometry/abm_patch/patch_side.h"

namespace isotrace {

// Throws std::invalid_argument naming the two curves, their end points and the gap when side i's end and side
// i+1's start (mod N) are farther apart than `tolerance`; when the gap closes with one of them run backwards, the
// message says so.
void check_closed_loop(const std::vector<PatchSide>& sides, double tolerance);

// Throws std::invalid_argument for a side whose curve has (nearly) zero length: it cannot bound a patch.
void check_not_degenerate(const std::vector<PatchSide>& sides);

}  // namespace isotrace
