#include "geometry/superquadric/cone_about_z.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isotrace {

// As the superellipsoid's quadrics take it: within the box the squares are a few units, rounded to 10⁻¹⁵.
constexpr double kMargin = 1e-8;

std::optional<Interval> ConeAboutZ::stretch(const Vec3d& start, const Vec3d& direction, double length) const {
    // q(τ) = X² + Y² − W² along the segment, X = kx·x, Y = ky·y, W = (α + β·z)·√(1 + margin): a·τ² + 2·b·τ + c.
    const double widen = std::sqrt(1 + kMargin);
    const double x0 = kx * start.x, x1 = kx * direction.x, y0 = ky * start.y, y1 = ky * direction.y;
    const double w0 = radius_scale(start.z) * widen, w1 = beta * direction.z * widen;
    const double a = x1 * x1 + y1 * y1 - w1 * w1, b = x0 * x1 + y0 * y1 - w0 * w1, c = x0 * x0 + y0 * y0 - w0 * w0;
    const auto clipped = [&](double lo, double hi) -> std::optional<Interval> {
        const Interval within{std::max(0.0, lo), std::min(length, hi)};
        return within.lo <= within.hi ? std::optional<Interval>(within) : std::nullopt;
    };
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double discriminant = b * b - a * c;
    if (a == 0) {  // along a generator of the cone: q is linear
        if (b == 0) return c <= 0 ? clipped(0, length) : std::nullopt;
        const double root = -c / (2 * b);
        return b > 0 ? clipped(-inf, root) : clipped(root, inf);
    }
    if (discriminant < 0) return a > 0 ? std::nullopt : clipped(0, length);  // q keeps a's sign throughout
    // The roots without cancellation.
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double r1 = q / a, r2 = q != 0 ? c / q : r1;
    if (r1 > r2) std::swap(r1, r2);
    if (a > 0) return clipped(r1, r2);
    // a < 0: q ≤ 0 beyond the roots, on both nappes; the segment, where α + β·z > 0, meets only one of them.
    const std::optional<Interval> before = clipped(-inf, r1), after = clipped(r2, inf);
    if (before && after) return clipped(0, length);  // only where the segment leaves α + β·z > 0: settles nothing
    return before ? before : after;
}

}  // namespace isotrace
