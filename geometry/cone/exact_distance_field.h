#pragma once
// A field that is an exact signed distance (the frustum's, the torus's) answers the bound queries from that alone:
// a distance changes by at most the distance moved (it is 1-Lipschitz), so over a box it lies within the half
// diagonal of its value at the centre, its slope along a direction is at most the direction's length, and the
// surface is within `radius` of a point exactly when |value| ≤ radius.
#include <cmath>

#include "renderer/plugin/implicit_field.h"

namespace isotrace {

class ExactDistanceField : public ImplicitField {
public:
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        return std::abs(value(centre)) <= radius;
    }
    Interval value_range(const IntervalBox& box) const override {
        const double centre_value = value((box.lower() + box.upper()) * 0.5);
        const double half_diagonal = 0.5 * length(box.upper() - box.lower());
        // Widened by a few ulps of the terms, for the rounding of the centre's value and of the diagonal.
        const double margin = 4e-16 * (std::abs(centre_value) + half_diagonal);
        return {centre_value - half_diagonal - margin, centre_value + half_diagonal + margin};
    }
    Interval slope_range(const IntervalBox&, const Vec3d& direction) const override {
        const double bound = length(direction) * (1 + 4e-16);
        return {-bound, bound};
    }
};

}  // namespace isotrace
