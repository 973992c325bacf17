#pragma once
// Interpolating B-spline curves: through points at given parameters (global interpolation, Piegl & Tiller
// §9.2.1), with chord-length parameters for points in space, and closed (periodic) uniform cubic splines
// through equally spaced samples, which are C² everywhere including the seam.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/curves/bspline_curve.h"
#include "geometry/curves/dense_solve.h"
#include "renderer/math/vec3.h"

namespace isotrace {

// Largest number of points the interpolators accept (they solve a dense system).
inline constexpr std::size_t kMaxInterpolatedPoints = 512;

// Cumulative chord lengths normalised to [0, 1]. Throws std::invalid_argument when there are fewer than two
// points, a point is not finite or two consecutive points coincide.
std::vector<double> chord_length_parameters(const std::vector<Vec3d>& points);

// The degree-p B-spline through values[k] at t = parameters[k] (strictly increasing from 0 to 1), with averaged
// clamped knots. The degree is lowered to count − 1 when there are fewer than p + 1 values. Throws
// std::invalid_argument for fewer than two values, more than kMaxInterpolatedPoints or bad parameters.
template <class P>
BSplineCurve<P> interpolate_curve(const std::vector<P>& values, const std::vector<double>& parameters, int degree);

// The knots interpolate_curve uses for these parameters (so that several curves can share one basis).
KnotVector interpolation_knots(const std::vector<double>& parameters, int degree);

// The closed uniform cubic B-spline through samples[j] at s = j/m (m = samples.size() ≥ 3), periodic in s with
// period 1: evaluate with PeriodicCurve.
template <class P>
class PeriodicCurve {
public:
    explicit PeriodicCurve(BSplineCurve<P> one_period) : curve_(std::move(one_period)) {}
    P operator()(double s) const { return curve_(s - std::floor(s)); }
    PeriodicCurve derivative() const { return PeriodicCurve(curve_.derivative()); }
    const BSplineCurve<P>& curve() const { return curve_; }

private:
    BSplineCurve<P> curve_;
};

// Control points c_j of the periodic uniform cubic B-spline through the samples: (c_{j−1} + 4c_j + c_{j+1})/6 =
// samples[j], indices modulo m. Exposed for tensor-product surfaces that interpolate in two directions.
template <class P>
std::vector<P> periodic_cubic_control_points(const std::vector<P>& samples);

template <class P>
PeriodicCurve<P> interpolate_periodic_cubic(const std::vector<P>& samples);

// ---- implementation ----

template <class P>
BSplineCurve<P> interpolate_curve(const std::vector<P>& values, const std::vector<double>& parameters, int degree) {
    if (parameters.size() != values.size()) throw std::invalid_argument("interpolation needs one parameter per point");
    KnotVector knots = interpolation_knots(parameters, degree);
    const int p = knots.degree();
    const std::size_t n = values.size();
    std::vector<double> matrix(n * n, 0.0);
    double basis[KnotVector::kMaxDegree + 1];
    for (std::size_t k = 0; k < n; ++k) {
        const int span = knots.span(parameters[k]);
        knots.basis(span, parameters[k], basis);
        for (int j = 0; j <= p; ++j) matrix[k * n + std::size_t(span - p + j)] = basis[j];
    }
    return {std::move(knots), solve_dense(std::move(matrix), values)};
}

template <class P>
std::vector<P> periodic_cubic_control_points(const std::vector<P>& samples) {
    const std::size_t m = samples.size();
    if (m < 3 || m > kMaxInterpolatedPoints)
        throw std::invalid_argument("a closed cubic spline needs 3 to " + std::to_string(kMaxInterpolatedPoints) +
                                    " samples, got " + std::to_string(m));
    std::vector<double> matrix(m * m, 0.0);
    for (std::size_t j = 0; j < m; ++j) {
        matrix[j * m + (j + m - 1) % m] += 1.0 / 6;
        matrix[j * m + j] += 4.0 / 6;
        matrix[j * m + (j + 1) % m] += 1.0 / 6;
    }
    return solve_dense(std::move(matrix), samples);
}

template <class P>
PeriodicCurve<P> interpolate_periodic_cubic(const std::vector<P>& samples) {
    const std::vector<P> c = periodic_cubic_control_points(samples);
    const std::size_t m = c.size();
    // One period of a uniform cubic B-spline: the m controls wrapped by one before and two after.
    std::vector<P> wrapped{c[m - 1]};
    wrapped.insert(wrapped.end(), c.begin(), c.end());
    wrapped.push_back(c[0]);
    wrapped.push_back(c[1]);
    return PeriodicCurve<P>(BSplineCurve<P>(KnotVector::uniform(3, int(m) + 3), std::move(wrapped)));
}

}  // namespace isotrace
