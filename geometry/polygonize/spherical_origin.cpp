#include "geometry/polygonize/spherical_origin.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/polygonize/neighbour_directions.h"
#include "renderer/math/box_corner.h"

namespace isotrace {
namespace {

// f at p + distance·d for the 26 directions d, times `side`: how far each probe lies on the origin's side.
std::array<double, 26> probes(const ImplicitField& field, const Vec3d& p, double distance, double side) {
    std::array<double, 26> values{};
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = side * field.value(p + neighbour_directions()[i] * distance);
    return values;
}

// Clear of the surface: on the wanted side, an estimated distance |f|/|∇f| of at least `reach` where the gradient
// gives one, and no sign change towards any of the 26 probes at half that distance. The probes catch what the
// estimate cannot see: a zero or undefined gradient (a saddle where two blobs touch, a hard cube's flat field, the
// centre of a sphere's distance) says nothing about the distance.
bool clear_of_surface(const ImplicitField& field, const Vec3d& p, double f, double slope, double side, double reach) {
    if (!(side * f > 0)) return false;
    if (slope > 0 && std::isfinite(slope) && std::abs(f) < reach * slope) return false;
    const std::array<double, 26> values = probes(field, p, reach / 2, side);
    return std::all_of(values.begin(), values.end(), [](double v) { return v > 0; });
}

}  // namespace

OriginCorrection correct_origin(const ImplicitField& field, const Vec3d& origin, int depth) {
    const double cell = max_component(field.bounds().extent()) / double(1 << depth);
    OriginCorrection result{origin};
    const double side = field.value(origin) > 0 ? 1.0 : -1.0;
    for (;; ++result.steps) {
        const double f = field.value(result.origin);
        const Vec3d g = field.gradient(result.origin);
        const double slope = length(g);
        if (clear_of_surface(field, result.origin, f, slope, side, 2 * cell)) {
            result.converged = true;
            return result;
        }
        if (result.steps == kMaxOriginSteps) return result;
        if (slope > 0 && std::isfinite(slope)) {
            result.origin += g * (side * cell / slope);
            continue;
        }
        // No gradient to follow: step to the probe one cell away that lies deepest on the wanted side.
        const std::array<double, 26> values = probes(field, result.origin, cell, side);
        const std::size_t best = std::size_t(std::max_element(values.begin(), values.end()) - values.begin());
        if (!(values[best] > side * f)) return result;  // flat all round: nowhere to go
        result.origin += neighbour_directions()[best] * cell;
    }
}

SphericalRange spherical_range(const ImplicitField& field, const Vec3d& origin) {
    const FieldBox box = field.bounds();
    double r_max = 0;
    for (int corner = 0; corner < 8; ++corner)
        r_max = std::max(r_max, length(box_corner(box.lower, box.upper, corner) - origin));
    r_max *= 1.02;
    double clear = 0, reached = r_max;  // no surface within `clear`; maybe some within `reached`
    for (int iteration = 0; iteration < 40; ++iteration) {
        const double r = (clear + reached) / 2;
        (field.may_reach_surface(origin, r) ? reached : clear) = r;
    }
    return {origin, std::max(0.9 * clear, kMinRadiusFraction * r_max), r_max};
}

}  // namespace isotrace
