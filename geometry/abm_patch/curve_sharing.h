#pragma once
// Patches share a boundary curve when they name the same one; a curve written out again for the neighbouring
// patch (inline, or under another name) is a different curve to the tessellation, which samples each curve on its
// own and would leave a crack of T-junctions between the patches. Coincident curves are found by their geometry:
// identical ones become one curve, nearly identical ones are an error.
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "geometry/abm_patch/abm_patch.h"

namespace isotrace {

// Two curves whose ends are this close (relative to the shorter one's length) and which stay this close between
// them are taken to be meant as one curve: closer than the tolerance they are welded, otherwise refused.
inline constexpr double kNearlySharedFraction = 0.01;
// Parameters at which two curves are compared (equally spaced, ends included).
inline constexpr int kCurveComparisonSamples = 64;

// A side of a patch whose curve nearly but not exactly coincides with the curve of an earlier patch.
class NearlySharedCurve : public std::invalid_argument {
public:
    NearlySharedCurve(std::size_t patch, std::size_t side, const std::string& message)
        : std::invalid_argument(message), patch(patch), side(side) {}
    std::size_t patch, side;
};

// The patches with every side whose curve coincides with the curve of an earlier patch's side — within
// `tolerance` at kCurveComparisonSamples equal parameters, in either direction — running along that earlier curve
// instead, so that the patches share it. Throws NearlySharedCurve for a curve of a later patch whose ends lie within
// kNearlySharedFraction of its length of an earlier patch's curve's ends and which stays within that distance of it,
// but not within `tolerance`.
std::vector<AbmPatch> share_coincident_curves(const std::vector<AbmPatch>& patches, double tolerance);

}  // namespace isotrace
