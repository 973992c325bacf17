#pragma once
// The part of a segment inside an axis-aligned ellipsoid or elliptic cylinder about the origin.
#include <algorithm>
#include <cmath>
#include <optional>

#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"

namespace isotrace {

// The line's τ where Σ (kᵢ·(sᵢ + τ·dᵢ))² is least, given s = k·start and d = k·direction with a = d·d > 0.
inline double nearest_of_scaled(const Vec3d& s, const Vec3d& d, double a) { return -dot(s, d) / a; }

// The τ in [0, length] where Σ (kᵢ·(startᵢ + τ·directionᵢ))² is least (0 where the line does not move in it).
inline double nearest_in_quadric(const Vec3d& k, const Vec3d& start, const Vec3d& direction, double length) {
    const Vec3d s = k * start, d = k * direction;
    const double a = dot(d, d);
    return a > 0 ? std::clamp(nearest_of_scaled(s, d, a), 0.0, length) : 0;
}

// The τ in [0, length] where Σ (kᵢ·(sᵢ + τ·dᵢ))² ≤ bound (a zero kᵢ leaves axis i out): about the line's point
// nearest the centre, found without cancellation; nothing where the segment misses the quadric.
inline std::optional<Interval> within_quadric(const Vec3d& k, const Vec3d& start, const Vec3d& direction, double length,
                                              double bound) {
    const Vec3d s = k * start, d = k * direction;
    const double a = dot(d, d);
    if (!(a > 0)) return dot(s, s) <= bound ? std::optional<Interval>(Interval{0, length}) : std::nullopt;
    const double middle = nearest_of_scaled(s, d, a);
    const Vec3d nearest = s + d * middle;
    const double room = bound - dot(nearest, nearest);
    if (room < 0) return std::nullopt;
    const double half = std::sqrt(room / a);
    const Interval within{std::max(0.0, middle - half), std::min(length, middle + half)};
    return within.lo <= within.hi ? std::optional<Interval>(within) : std::nullopt;
}

}  // namespace isotrace
