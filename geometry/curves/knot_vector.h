#pragma once
// A B-spline basis: degree p and a non-decreasing knot vector u_0 … u_{n+p+1} for n+1 control points. Curves
// built on it take a parameter t normalised to [0, 1], mapped linearly onto the valid domain [u_p, u_{n+1}], so
// that users of the curves (sweeps, multi-sided patch boundaries) never see knot values.
#include <vector>

namespace isotrace {

class KnotVector {
public:
    static constexpr int kMaxDegree = 16;

    // Throws std::invalid_argument unless 0 ≤ degree ≤ kMaxDegree, there are at least degree + 1 control points
    // (knots.size() − degree − 1), the knots are finite and non-decreasing and the domain has positive length.
    KnotVector(int degree, std::vector<double> knots);

    // End knots repeated degree + 1 times, interior knots equally spaced: the curve starts and ends at its first
    // and last control points.
    static KnotVector clamped_uniform(int degree, int control_count);
    // Equally spaced knots 0, 1, 2, …: every basis function is a shifted copy of one another.
    static KnotVector uniform(int degree, int control_count);
    // Clamped knots for interpolating at `parameters` (increasing, in [0, 1]) by averaging p consecutive
    // parameters (Piegl & Tiller, eq. 9.8): the interpolation matrix is then totally positive and banded.
    static KnotVector averaged(int degree, const std::vector<double>& parameters);

    int degree() const { return degree_; }
    int control_count() const { return int(knots_.size()) - degree_ - 1; }
    const std::vector<double>& knots() const { return knots_; }
    double domain_start() const { return knots_[std::size_t(degree_)]; }
    double domain_end() const { return knots_[std::size_t(control_count())]; }

    // t ∈ [0, 1] (clamped) to the knot parameter u in the domain.
    double to_knot(double t) const;
    // Index i of the knot span [u_i, u_{i+1}) holding u, with degree ≤ i ≤ control_count − 1 (the last span
    // is closed at the domain end).
    int span(double u) const;
    // The degree + 1 basis functions N_{span−p} … N_{span} at u (Cox–de Boor, Piegl & Tiller A2.2).
    void basis(int span, double u, double* values) const;

private:
    int degree_;
    std::vector<double> knots_;
};

}  // namespace isotrace
