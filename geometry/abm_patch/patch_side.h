#pragma once
// One side of a patch: a boundary curve, possibly run backwards, so that the curves of a loop each run into the
// next and two patches can share one curve (each in its own direction); optionally with a cross-boundary tangent
// (smooth joins).
#include <memory>
#include <string>
#include <utility>

#include "geometry/abm_patch/cross_tangent.h"
#include "geometry/curves/space_curve.h"

namespace isotrace {

struct PatchSide {
    std::shared_ptr<const SpaceCurve> curve;
    bool reversed = false;
    std::string name;  // for messages: "curve 2" or the scene's curve name
    std::shared_ptr<const CrossTangent> ribbon{};  // in the side's own parameter; none: the side's attribute is c

    Vec3d point(double t) const { return (*curve)(reversed ? 1 - t : t); }
    // The point and the derivative along the side's own direction.
    std::pair<Vec3d, Vec3d> point_and_tangent(double t) const {
        if (!reversed) return curve->value_and_tangent(t);
        const auto [value, tangent] = curve->value_and_tangent(1 - t);
        return {value, -1.0 * tangent};
    }
    Vec3d start() const { return point(0); }
    Vec3d end() const { return point(1); }
};

}  // namespace isotrace
