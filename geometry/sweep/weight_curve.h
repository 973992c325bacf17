#pragma once
// The influence weight f(u) of local deformation (the paper's eq. 9 and Fig. 4): a B-spline in u = (r + d)/r,
// the vertex's relative distance from the sweep's axis (0 on the axis, 1 on the surface). Its control values
// must lie in [0, 1], so that f does too (convex hull). Default: the clamped cubic with control values
// 1, 1, 0, 0 — weight 1 on the axis falling smoothly to 0 at the surface, with zero slope at both ends.
#include <vector>

#include "geometry/curves/bspline_curve.h"

namespace isotrace {

class WeightCurve {
public:
    WeightCurve();
    // Clamped uniform knots of the given degree (lowered to count − 1 for few values). Throws
    // std::invalid_argument "weight_curve[k]: ..." for a value outside [0, 1] or not finite, or fewer than 2 values.
    explicit WeightCurve(const std::vector<double>& control_values, int degree = 3);

    // f(u) for an inner vertex (u clamped to [0, 1]).
    double operator()(double u) const { return curve_(u); }

private:
    BSplineCurve<double> curve_;
};

}  // namespace isotrace
