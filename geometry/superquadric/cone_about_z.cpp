#include "geometry/superquadric/cone_about_z.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/polynomial/quadratic_negative_pieces.h"

namespace isotrace {

// As the superellipsoid's quadrics take it: within the box the squares are a few units, rounded to 10⁻¹⁵.
constexpr double kMargin = 1e-8;

std::optional<Interval> ConeAboutZ::stretch(const Vec3d& start, const Vec3d& direction, double length) const {
    // q(τ) = X² + Y² − W² along the segment, X = kx·x, Y = ky·y, W = (α + β·z)·√(1 + margin): a·τ² + b·τ + c.
    const double widen = std::sqrt(1 + kMargin);
    const double x0 = kx * start.x, x1 = kx * direction.x, y0 = ky * start.y, y1 = ky * direction.y;
    const double w0 = radius_scale(start.z) * widen, w1 = beta * direction.z * widen;
    const double a = x1 * x1 + y1 * y1 - w1 * w1, b = 2 * (x0 * x1 + y0 * y1 - w0 * w1), c = x0 * x0 + y0 * y0 - w0 * w0;
    std::array<NegativePiece, 2> pieces;
    const int count = negative_pieces(a, b, c, quadratic_roots(a, b, c), pieces);
    // The segment, where α + β·z > 0, meets one nappe only, so one piece; should it meet both (only where it left
    // α + β·z > 0), the whole segment, which settles nothing.
    std::optional<Interval> within;
    for (int i = 0; i < count; ++i) {
        const Interval part{std::max(0.0, pieces[i].lo), std::min(length, pieces[i].hi)};
        if (!(part.lo <= part.hi)) continue;
        within = within ? Interval{0, length} : part;
    }
    return within;
}

}  // namespace isotrace
