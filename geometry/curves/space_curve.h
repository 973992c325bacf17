#pragma once
// A curve in space of any of the layer's kinds — Bézier, uniform or non-uniform B-spline, NURBS — behind one type,
// for code that takes "a curve" from a scene (multi-sided patch boundaries). Polynomial curves are rational
// curves with unit weights. The parameter t is normalised to [0, 1].
#include <utility>
#include <vector>

#include "geometry/curves/rational_curve.h"
#include "renderer/math/vec3.h"

namespace isotrace {

class SpaceCurve {
public:
    // `weights` empty: a polynomial (non-rational) curve. Throws std::invalid_argument for a control point that
    // is not finite, a knot/point count mismatch or bad weights.
    SpaceCurve(KnotVector knots, std::vector<Vec3d> points, const std::vector<double>& weights = {});

    static SpaceCurve bezier(std::vector<Vec3d> points);

    Vec3d operator()(double t) const { return curve_.value_and_tangent(t).first; }
    // The point and dC/dt.
    std::pair<Vec3d, Vec3d> value_and_tangent(double t) const { return curve_.value_and_tangent(t); }
    const std::vector<Vec3d>& control_points() const { return points_; }

    // Length of the polyline through `samples` + 1 equally spaced points (a lower bound of the arc length).
    double polyline_length(int samples) const;

private:
    std::vector<Vec3d> points_;
    RationalCurve<Vec3d> curve_;
};

}  // namespace isotrace
