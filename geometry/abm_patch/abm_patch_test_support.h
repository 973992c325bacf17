#pragma once
// Curved boundary loops for the patch tests.
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "geometry/abm_patch/abm_patch.h"

namespace isotrace::abm_test {

inline std::shared_ptr<const SpaceCurve> bezier(std::vector<Vec3d> points) {
    return std::make_shared<const SpaceCurve>(SpaceCurve::bezier(std::move(points)));
}

inline PatchSide side(std::shared_ptr<const SpaceCurve> curve, bool reversed = false) {
    return {std::move(curve), reversed, "curve"};
}

// N cubic curves between the corners of a bumpy N-gon in space: corners on a circle with alternating heights,
// inner control points bulging outward and up. Closed: each curve ends where the next starts.
inline std::vector<PatchSide> curved_loop(int n) {
    std::vector<Vec3d> corners;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * k / n;
        corners.push_back({std::cos(a), std::sin(a), 0.2 * (k % 2) - 0.1 * k / n});
    }
    std::vector<PatchSide> sides;
    for (int k = 0; k < n; ++k) {
        const Vec3d a = corners[std::size_t(k)], b = corners[std::size_t((k + 1) % n)];
        const Vec3d out = 0.25 * (a + b) + Vec3d{0, 0, 0.3 + 0.05 * k};
        sides.push_back(side(bezier({a, a + (1.0 / 3) * (b - a) + out, a + (2.0 / 3) * (b - a) + 0.5 * out, b})));
    }
    return sides;
}

}  // namespace isotrace::abm_test
