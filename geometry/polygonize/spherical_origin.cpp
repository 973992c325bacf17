#include "geometry/polygonize/spherical_origin.h"

#include <algorithm>
#include <cmath>

#include "renderer/math/box_corner.h"

namespace isotrace {

OriginCorrection correct_origin(const ImplicitField& field, const Vec3d& origin, int depth) {
    const double cell = max_component(field.bounds().extent()) / double(1 << depth);
    OriginCorrection result{origin};
    const double side = field.value(origin) > 0 ? 1.0 : -1.0;
    for (;; ++result.steps) {
        const double f = field.value(result.origin);
        const Vec3d g = field.gradient(result.origin);
        const double slope = length(g);
        if (std::abs(f) >= 2 * cell * slope && (f > 0) == (side > 0) && f != 0) {
            result.converged = true;
            return result;
        }
        if (result.steps == kMaxOriginSteps || !(slope > 0) || !std::isfinite(slope)) return result;
        result.origin += g * (side * cell / slope);
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
    return {origin, std::max(0.9 * clear, 1e-3 * r_max), r_max};
}

}  // namespace isotrace
