#include "geometry/sweep/weight_curve.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace isotrace {
namespace {

BSplineCurve<double> checked_curve(const std::vector<double>& values, int degree) {
    if (values.size() < 2 || values.size() > 64)
        throw std::invalid_argument("weight_curve: needs 2 to 64 control values, got " + std::to_string(values.size()));
    for (std::size_t k = 0; k < values.size(); ++k)
        if (!(values[k] >= 0 && values[k] <= 1)) {
            std::ostringstream problem;
            problem << "weight_curve[" << k << "]: control value " << values[k] << " is outside [0, 1]";
            throw std::invalid_argument(problem.str());
        }
    const int p = std::clamp(degree, 1, int(values.size()) - 1);
    return {KnotVector::clamped_uniform(p, int(values.size())), values};
}

}  // namespace

WeightCurve::WeightCurve() : WeightCurve({1, 1, 0, 0}) {}

WeightCurve::WeightCurve(const std::vector<double>& control_values, int degree)
    : curve_(checked_curve(control_values, degree)) {}

}  // namespace isotrace
