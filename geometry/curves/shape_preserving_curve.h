#pragma once
// Shape-preserving interpolation (Fritsch & Carlson, "Monotone Piecewise Cubic Interpolation"; tangents by the
// weighted harmonic mean of Fritsch & Butland): a C¹ piecewise cubic through values[k] at t = parameters[k]
// whose slope at a key is zero where the data turn and never so steep that a piece overshoots. Between two
// keys it stays within their values, so a scaled key section cannot make its neighbours shrink (as the
// interpolating cubic B-spline does). Points in space: each coordinate on its own. Built as a cubic B-spline
// with triple interior knots (one Bézier piece per key interval), so it evaluates like any other curve.
#include <vector>

#include "geometry/curves/bspline_curve.h"
#include "renderer/math/vec3.h"

namespace isotrace {

// The knots of the curve for these parameters (strictly increasing from 0 to 1): 0 and 1 four times, every
// interior parameter three times.
KnotVector shape_preserving_knots(const std::vector<double>& parameters);

// The curve's slope at each key for scalar values (same length as `parameters`, at least 2).
std::vector<double> shape_preserving_slopes(const std::vector<double>& values, const std::vector<double>& parameters);

// The B-spline control points of the curve: per key interval its Bézier points, end points shared.
std::vector<double> shape_preserving_control_points(const std::vector<double>& values, const std::vector<double>& parameters);
std::vector<Vec3d> shape_preserving_control_points(const std::vector<Vec3d>& values, const std::vector<double>& parameters);

template <class P>
BSplineCurve<P> shape_preserving_curve(const std::vector<P>& values, const std::vector<double>& parameters) {
    return BSplineCurve<P>(shape_preserving_knots(parameters), shape_preserving_control_points(values, parameters));
}

}  // namespace isotrace
