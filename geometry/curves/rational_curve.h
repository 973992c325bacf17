#pragma once
// Rational B-spline (NURBS) curves: a B-spline of homogeneous points (w·P, w), projected back by dividing by w.
// Conics and circles are exact. Derivatives by the quotient rule on the homogeneous curve's derivatives.
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geometry/curves/bspline_curve.h"

namespace isotrace {

template <class P>
struct Homogeneous {
    P weighted{};  // w · P
    double weight = 0;

    friend Homogeneous operator+(const Homogeneous& a, const Homogeneous& b) {
        return {a.weighted + b.weighted, a.weight + b.weight};
    }
    friend Homogeneous operator-(const Homogeneous& a, const Homogeneous& b) {
        return {a.weighted - b.weighted, a.weight - b.weight};
    }
    friend Homogeneous operator*(double s, const Homogeneous& a) { return {s * a.weighted, s * a.weight}; }
};

template <class P>
class RationalCurve {
public:
    // Throws std::invalid_argument unless there is one weight per point and every weight is finite and > 0.
    RationalCurve(KnotVector knots, const std::vector<P>& points, const std::vector<double>& weights)
        : homogeneous_(BSplineCurve<Homogeneous<P>>(std::move(knots), lift(points, weights))) {}

    P operator()(double t) const {
        const Homogeneous<P> h = homogeneous_(t);
        return (1.0 / h.weight) * h.weighted;
    }

    // The point and dC/dt, without the second derivative.
    std::pair<P, P> value_and_tangent(double t) const {
        const Homogeneous<P> h = homogeneous_(t), first = homogeneous_.first(t);
        const double inverse = 1.0 / h.weight;
        const P value = inverse * h.weighted;
        return {value, inverse * (first.weighted - first.weight * value)};
    }

    CurveJet<P> jet(double t) const {
        const CurveJet<Homogeneous<P>> h = homogeneous_.jet(t);
        const double inverse = 1.0 / h.value.weight;
        CurveJet<P> c;
        c.value = inverse * h.value.weighted;
        c.first = inverse * (h.first.weighted - h.first.weight * c.value);
        c.second = inverse * (h.second.weighted - (2 * h.first.weight) * c.first - h.second.weight * c.value);
        return c;
    }

private:
    static std::vector<Homogeneous<P>> lift(const std::vector<P>& points, const std::vector<double>& weights) {
        if (points.size() != weights.size())
            throw std::invalid_argument("weights: need one per control point (" + std::to_string(points.size()) +
                                        "), got " + std::to_string(weights.size()));
        std::vector<Homogeneous<P>> lifted;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (!(weights[i] > 0) || !std::isfinite(weights[i]))
                throw std::invalid_argument("weights[" + std::to_string(i) + "]: must be finite and > 0");
            lifted.push_back({weights[i] * points[i], weights[i]});
        }
        return lifted;
    }

    DifferentiableCurve<Homogeneous<P>> homogeneous_;
};

}  // namespace isotrace
