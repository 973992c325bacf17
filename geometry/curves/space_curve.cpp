#include "geometry/curves/space_curve.h"

#include <stdexcept>
#include <string>

namespace isotrace {
namespace {

std::vector<Vec3d> checked(std::vector<Vec3d> points) {
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!is_finite(points[i]))
            throw std::invalid_argument("points[" + std::to_string(i) + "]: a control point must be finite");
    return points;
}

}  // namespace

SpaceCurve::SpaceCurve(KnotVector knots, std::vector<Vec3d> points, const std::vector<double>& weights)
    : points_(checked(std::move(points))),
      curve_(std::move(knots), points_, weights.empty() ? std::vector<double>(points_.size(), 1.0) : weights) {}

SpaceCurve SpaceCurve::bezier(std::vector<Vec3d> points) {
    if (points.size() < 2) throw std::invalid_argument("points: a Bézier curve needs at least two");
    const BSplineCurve<Vec3d> curve = bezier_curve(std::move(points));
    return {curve.knots(), curve.control_points()};
}

double SpaceCurve::polyline_length(int samples) const {
    double total = 0;
    Vec3d previous = (*this)(0);
    for (int k = 1; k <= samples; ++k) {
        const Vec3d next = (*this)(double(k) / samples);
        total += length(next - previous);
        previous = next;
    }
    return total;
}

}  // namespace isotrace
