#include "geometry/superquadric/bend_sector.h"

#include <algorithm>
#include <limits>

#include "geometry/superquadric/within_quadric.h"

namespace isotrace {

// As the superellipsoid's quadrics take it: in the scaled coordinates the squares are about one, rounded to 10⁻¹⁶.
constexpr double kMargin = 1e-8;

std::optional<Interval> BendSector::stretch(const Vec3d& start, const Vec3d& direction, double length) const {
    // The segment about the centre, scaled by k, in the plane of u and z (the bend leaves the third axis alone).
    const Vec3d from{curvature * dot(start, toward) - 1, curvature * (start.z - centre), 0};
    const Vec3d along{curvature * dot(direction, toward), curvature * direction.z, 0};
    const Vec3d plane{1, 1, 0};
    std::optional<Interval> part = within_quadric(plane, from, along, length, outer * outer * (1 + kMargin));
    if (!part) return std::nullopt;
    // The wedge: a point at angle θ about the centre lies along (−cos θ, sin θ), so a·sin θlo + b·cos θlo ≥ 0 above the
    // lowest cross-section and a·sin θhi + b·cos θhi ≤ 0 below the highest (the wedge is at most half a turn).
    constexpr double inf = std::numeric_limits<double>::infinity();
    const auto keep_where_positive = [&](double value, double rate) {  // value + τ·rate ≥ −margin
        const double shifted = value + kMargin;
        if (rate == 0) {
            if (shifted < 0) part.reset();
            return;
        }
        const double root = -shifted / rate;
        const Interval half = rate > 0 ? Interval{root, inf} : Interval{-inf, root};
        const Interval both{std::max(part->lo, half.lo), std::min(part->hi, half.hi)};
        if (both.lo <= both.hi) part = both;
        else part.reset();
    };
    keep_where_positive(from.x * sin_lo + from.y * cos_lo, along.x * sin_lo + along.y * cos_lo);
    if (part) keep_where_positive(-(from.x * sin_hi + from.y * cos_hi), -(along.x * sin_hi + along.y * cos_hi));
    if (!part || !(inner > 0)) return part;
    // The hole inside the inner cylinder, narrowed by the margin, holds none of the object.
    const std::optional<Interval> hole = within_quadric(plane, from, along, length, inner * inner * (1 - kMargin));
    if (!hole) return part;
    if (hole->lo <= part->lo && hole->hi >= part->hi) return std::nullopt;
    Interval trimmed = *part;
    if (hole->lo <= trimmed.lo && hole->hi > trimmed.lo) trimmed.lo = hole->hi;
    if (hole->hi >= trimmed.hi && hole->lo < trimmed.hi) trimmed.hi = hole->lo;
    return trimmed;
}

}  // namespace isotrace
