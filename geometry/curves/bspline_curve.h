#pragma once
// A B-spline curve of any degree over a KnotVector, with control points of any vector-space type P (P + P,
// P − P, double · P; a value-initialised P is zero): numbers, Vec3d, quaternions, homogeneous points.
// The parameter t is normalised to [0, 1] (values outside are clamped); derivatives are with respect to t.
// Bézier curves are the B-splines of one segment (bezier_curve), uniform and non-uniform B-splines differ only
// in their knots, and rational curves (rational_curve.h) are B-splines of homogeneous points.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geometry/curves/knot_vector.h"

namespace isotrace {

template <class P>
class BSplineCurve {
public:
    BSplineCurve(KnotVector knots, std::vector<P> control_points)
        : knots_(std::move(knots)), control_(std::move(control_points)) {
        if (int(control_.size()) != knots_.control_count())
            throw std::invalid_argument("control_points: the knots need " + std::to_string(knots_.control_count()) +
                                        " control points, got " + std::to_string(control_.size()));
    }

    const KnotVector& knots() const { return knots_; }
    int degree() const { return knots_.degree(); }
    const std::vector<P>& control_points() const { return control_; }

    P operator()(double t) const {
        const double u = knots_.to_knot(t);
        const int span = knots_.span(u);
        double basis[KnotVector::kMaxDegree + 1];
        knots_.basis(span, u, basis);
        P sum{};
        for (int j = 0; j <= degree(); ++j) sum = sum + basis[j] * control_[std::size_t(span - degree() + j)];
        return sum;
    }

    // dC/dt as a curve of one degree less (Piegl & Tiller eq. 3.8, scaled by the domain length because t is
    // normalised). The derivative of a degree-0 curve is zero.
    BSplineCurve derivative() const {
        const int p = degree();
        const std::vector<double>& u = knots_.knots();
        if (p == 0) return {knots_, std::vector<P>(control_.size(), P{})};
        const double scale = knots_.domain_end() - knots_.domain_start();
        std::vector<P> points;
        for (std::size_t i = 0; i + 1 < control_.size(); ++i) {
            const double width = u[i + std::size_t(p) + 1] - u[i + 1];
            points.push_back(width == 0 ? P{} : (p * scale / width) * (control_[i + 1] - control_[i]));
        }
        return {KnotVector(p - 1, std::vector<double>(u.begin() + 1, u.end() - 1)), std::move(points)};
    }

private:
    KnotVector knots_;
    std::vector<P> control_;
};

// The Bézier curve of the given control points (degree = count − 1): one segment with clamped knots.
template <class P>
BSplineCurve<P> bezier_curve(std::vector<P> control_points) {
    if (control_points.empty()) throw std::invalid_argument("control_points: a Bézier curve needs at least one");
    const int degree = int(control_points.size()) - 1;
    return {KnotVector::clamped_uniform(degree, degree + 1), std::move(control_points)};
}

// A curve with its first and second derivative curves, for evaluating frames and velocities repeatedly.
template <class P>
struct CurveJet {
    P value, first, second;
};

template <class P>
class DifferentiableCurve {
public:
    explicit DifferentiableCurve(BSplineCurve<P> curve)
        : curve_(std::move(curve)), first_(curve_.derivative()), second_(first_.derivative()) {}

    const BSplineCurve<P>& curve() const { return curve_; }
    P operator()(double t) const { return curve_(t); }
    P first(double t) const { return first_(t); }
    P second(double t) const { return second_(t); }
    CurveJet<P> jet(double t) const { return {curve_(t), first_(t), second_(t)}; }

private:
    BSplineCurve<P> curve_, first_, second_;
};

}  // namespace isotrace
