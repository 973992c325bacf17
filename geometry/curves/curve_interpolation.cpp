#include "geometry/curves/curve_interpolation.h"

namespace isotrace {

std::vector<double> chord_length_parameters(const std::vector<Vec3d>& points) {
    if (points.size() < 2) throw std::invalid_argument("chord-length parameters need at least two points");
    std::vector<double> parameters{0.0};
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (!is_finite(points[i]) || !is_finite(points[i - 1]))
            throw std::invalid_argument("point " + std::to_string(is_finite(points[i]) ? i - 1 : i) + " is not finite");
        const double chord = length(points[i] - points[i - 1]);
        if (!(chord > 0))
            throw std::invalid_argument("points " + std::to_string(i - 1) + " and " + std::to_string(i) + " coincide");
        parameters.push_back(parameters.back() + chord);
    }
    const double total = parameters.back();
    for (double& t : parameters) t /= total;
    parameters.back() = 1;
    return parameters;
}

KnotVector interpolation_knots(const std::vector<double>& parameters, int degree) {
    if (parameters.size() < 2 || parameters.size() > kMaxInterpolatedPoints)
        throw std::invalid_argument("interpolation needs 2 to " + std::to_string(kMaxInterpolatedPoints) +
                                    " points, got " + std::to_string(parameters.size()));
    if (parameters.front() != 0 || parameters.back() != 1)
        throw std::invalid_argument("interpolation parameters must run from 0 to 1");
    for (std::size_t i = 1; i < parameters.size(); ++i)
        if (!(parameters[i] > parameters[i - 1]))
            throw std::invalid_argument("interpolation parameters must increase strictly");
    return KnotVector::averaged(std::min(degree, int(parameters.size()) - 1), parameters);
}

}  // namespace isotrace
