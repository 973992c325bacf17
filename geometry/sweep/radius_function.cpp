#include "geometry/sweep/radius_function.h"

#include <cmath>
#include <numbers>

#include "geometry/curves/curve_interpolation.h"
#include "geometry/curves/shape_preserving_curve.h"

namespace isotrace {
RadiusFunction::RadiusFunction(const std::vector<std::vector<double>>& radii, const std::vector<double>& parameters,
                               bool shape_preserving)
    : samples_(int(radii.front().size())),
      t_knots_(shape_preserving ? shape_preserving_knots(parameters) : interpolation_knots(parameters, 3)),
      theta_knots_(KnotVector::uniform(3, samples_ + 3)) {
    const std::size_t m = std::size_t(samples_);
    // θ first: the periodic control points of each key; then t: each θ control column interpolated over the keys.
    std::vector<std::vector<double>> per_key;
    for (const auto& r : radii) per_key.push_back(periodic_cubic_control_points(r));
    control_.resize(std::size_t(t_knots_.control_count()) * m);
    for (std::size_t j = 0; j < m; ++j) {
        std::vector<double> column;
        for (const auto& key : per_key) column.push_back(key[j]);
        const std::vector<double> points = shape_preserving ? shape_preserving_control_points(column, parameters)
                                                            : interpolate_curve(column, parameters, 3).control_points();
        for (std::size_t i = 0; i < points.size(); ++i) control_[i * m + j] = points[i];
    }
}

double RadiusFunction::operator()(double theta, double t) const {
    const int m = samples_;
    const double turns = theta / (2 * std::numbers::pi);
    const double v = theta_knots_.domain_start() + (turns - std::floor(turns)) * m;
    const int theta_span = theta_knots_.span(v);
    const double u = t_knots_.to_knot(t);
    const int t_span = t_knots_.span(u);
    double bt[KnotVector::kMaxDegree + 1], bv[4];
    t_knots_.basis(t_span, u, bt);
    theta_knots_.basis(theta_span, v, bv);
    const int pt = t_knots_.degree();
    double sum = 0;
    for (int a = 0; a <= pt; ++a) {
        const double* row = &control_[std::size_t(t_span - pt + a) * std::size_t(m)];
        double inner = 0;
        // Wrapped control w of one period is c[(w − 1) mod m] (see interpolate_periodic_cubic).
        for (int b = 0; b < 4; ++b) inner += bv[b] * row[(theta_span - 3 + b - 1 + m) % m];
        sum += bt[a] * inner;
    }
    return sum;
}

}  // namespace isotrace
