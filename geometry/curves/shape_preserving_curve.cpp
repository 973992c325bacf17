#include "geometry/curves/shape_preserving_curve.h"

#include <stdexcept>

namespace isotrace {

KnotVector shape_preserving_knots(const std::vector<double>& parameters) {
    if (parameters.size() < 2) throw std::invalid_argument("shape-preserving interpolation needs at least 2 values");
    std::vector<double> knots(4, parameters.front());
    for (std::size_t k = 1; k + 1 < parameters.size(); ++k) knots.insert(knots.end(), 3, parameters[k]);
    knots.insert(knots.end(), 4, parameters.back());
    return KnotVector(3, std::move(knots));
}

std::vector<double> shape_preserving_slopes(const std::vector<double>& values, const std::vector<double>& parameters) {
    const std::size_t n = values.size();
    std::vector<double> h(n - 1), delta(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        h[k] = parameters[k + 1] - parameters[k];
        delta[k] = (values[k + 1] - values[k]) / h[k];
    }
    std::vector<double> slope(n);
    slope.front() = delta.front();
    slope.back() = delta.back();
    for (std::size_t k = 1; k + 1 < n; ++k) {
        const double a = delta[k - 1], b = delta[k];
        // Zero where the data turn or stay level; otherwise a weighted harmonic mean, never beyond 3·min(|a|, |b|).
        slope[k] = a * b <= 0 ? 0 : 3 * (h[k - 1] + h[k]) / ((2 * h[k] + h[k - 1]) / a + (h[k] + 2 * h[k - 1]) / b);
    }
    return slope;
}

std::vector<double> shape_preserving_control_points(const std::vector<double>& values, const std::vector<double>& parameters) {
    const std::vector<double> slope = shape_preserving_slopes(values, parameters);
    std::vector<double> control{values.front()};
    for (std::size_t k = 0; k + 1 < values.size(); ++k) {
        const double third = (parameters[k + 1] - parameters[k]) / 3;
        control.push_back(values[k] + third * slope[k]);
        control.push_back(values[k + 1] - third * slope[k + 1]);
        control.push_back(values[k + 1]);
    }
    return control;
}

std::vector<Vec3d> shape_preserving_control_points(const std::vector<Vec3d>& values, const std::vector<double>& parameters) {
    std::vector<double> coordinate[3];
    for (const Vec3d& v : values)
        for (int a = 0; a < 3; ++a) coordinate[a].push_back(v[a]);
    std::vector<double> control[3];
    for (int a = 0; a < 3; ++a) control[a] = shape_preserving_control_points(coordinate[a], parameters);
    std::vector<Vec3d> points;
    for (std::size_t i = 0; i < control[0].size(); ++i) points.push_back({control[0][i], control[1][i], control[2][i]});
    return points;
}

}  // namespace isotrace
