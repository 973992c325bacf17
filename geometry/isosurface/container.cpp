#include "geometry/isosurface/container.h"

#include <algorithm>
#include <cmath>

#include "geometry/sphere/distance_range.h"
#include "geometry/sphere/sphere_intersection.h"
#include "renderer/math/line_box_clip.h"

namespace isotrace {

Container Container::box(const Vec3d& lower, const Vec3d& upper) {
    Container c;
    c.centre_ = (lower + upper) * 0.5;
    c.bounds_ = {{lower.x, upper.x}, {lower.y, upper.y}, {lower.z, upper.z}};
    return c;
}

Container Container::sphere(const Vec3d& centre, double radius) {
    Container c;
    c.is_sphere_ = true;
    c.centre_ = centre;
    c.radius_ = radius;
    const Vec3d r{radius, radius, radius};
    c.bounds_ = {{centre.x - r.x, centre.x + r.x}, {centre.y - r.y, centre.y + r.y}, {centre.z - r.z, centre.z + r.z}};
    return c;
}

std::optional<Interval> Container::clip(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max) const {
    if (!is_sphere_) {
        const auto c = clip_line_to_box(bounds_.lower(), bounds_.upper(), origin, direction, t_min, t_max);
        if (!c) return std::nullopt;
        return Interval{c->t_enter, c->t_exit};
    }
    const auto roots = intersect_sphere(origin, direction, centre_, radius_);
    if (!roots) return std::nullopt;
    const Interval inside{std::max(roots->t0, t_min), std::min(roots->t1, t_max)};
    if (!(inside.lo <= inside.hi)) return std::nullopt;
    return inside;
}

double Container::signed_distance(const Vec3d& p) const {
    if (is_sphere_) return length(p - centre_) - radius_;
    const Vec3d q = abs(p - centre_) - (bounds_.upper() - bounds_.lower()) * 0.5;
    return length(max(q, Vec3d{})) + std::min(max_component(q), 0.0);
}

Vec3d Container::normal(const Vec3d& p) const {
    const Vec3d offset = p - centre_;
    if (is_sphere_) return safe_normalize(offset, Vec3d{0, 0, 1});
    // The face whose plane p is nearest to (relative to the half size, so a point on a face picks that face).
    const Vec3d half = (bounds_.upper() - bounds_.lower()) * 0.5;
    int axis = 0;
    double best = -INFINITY;
    for (int k = 0; k < 3; ++k) {
        const double gap = std::abs(offset[k]) - half[k];
        if (gap > best) {
            best = gap;
            axis = k;
        }
    }
    Vec3d n;
    n[axis] = offset[axis] < 0 ? -1 : 1;
    return n;
}

Interval Container::distance_range(const IntervalBox& cell) const {
    if (is_sphere_) return ::isotrace::distance_range(cell, centre_) + (-radius_);
    // The box's signed distance is 1-Lipschitz: its value at the cell's centre, widened by the half diagonal.
    const Vec3d middle = (cell.lower() + cell.upper()) * 0.5;
    const double reach = 0.5 * length(cell.upper() - cell.lower());
    const double at_middle = signed_distance(middle);
    return {at_middle - reach, at_middle + reach};
}

bool Container::boundary_may_meet(const IntervalBox& cell) const { return distance_range(cell).contains(0); }

}  // namespace isotrace
