#include "geometry/sweep/sweep_fold.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "geometry/sweep/sweep_surface.h"

namespace isotrace {
namespace {

std::vector<double> sample_parameters(const SweepSurface& sweep) {
    const std::vector<double>& keys = sweep.key_parameters();
    std::vector<double> t;
    for (std::size_t k = 0; k + 1 < keys.size(); ++k)
        for (int i = 0; i < kFoldSamplesPerKey; ++i) t.push_back(keys[k] + (keys[k + 1] - keys[k]) * i / kFoldSamplesPerKey);
    t.push_back(1);
    return t;
}

// Whether every outline point of the section at `t` lies strictly on the `side` (+1 ahead, −1 behind) of the
// plane of the section at `plane`.
bool outline_on_side(const SweepSurface& sweep, double t, double plane, int side) {
    const Vec3d centre = sweep.centre(plane), normal = sweep.normal(plane);
    const int m = sweep.radius_samples();
    for (int j = 0; j < m; ++j)
        if (side * dot(sweep.point(2 * std::numbers::pi * j / m, t) - centre, normal) <= 0) return false;
    return true;
}

double ratio(double a, double b) { return a > b ? a / b : b / a; }

}  // namespace

std::string sweep_fold(const SweepSurface& sweep) {
    const std::vector<double> t = sample_parameters(sweep);
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
        if (outline_on_side(sweep, t[i + 1], t[i], 1) && outline_on_side(sweep, t[i], t[i + 1], -1)) continue;
        std::ostringstream problem;
        problem.precision(3);
        problem << "sections at t = " << t[i] << " and " << t[i + 1] << " cross";
        return problem.str();
    }
    return {};
}

double sweep_stretch(const SweepSurface& original, const SweepSurface& edited) {
    const std::vector<double> t = sample_parameters(original);
    double worst = 1;
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
        worst = std::max(worst, ratio(length(edited.centre(t[i + 1]) - edited.centre(t[i])),
                                      length(original.centre(t[i + 1]) - original.centre(t[i]))));
    for (std::size_t k = 0; k < original.keys().size(); ++k)
        for (std::size_t j = 0; j < original.keys()[k].radii.size(); ++j)
            worst = std::max(worst, ratio(edited.keys()[k].radii[j], original.keys()[k].radii[j]));
    return worst;
}

}  // namespace isotrace
