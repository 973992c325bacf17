#include "geometry/cone/frustum.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/polynomial/quadratic_negative_pieces.h"
#include "geometry/polynomial/quadratic_roots.h"

namespace isotrace {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The line in the frustum's frame with its origin moved to its point nearest the frustum's middle, which lies at
// t = shift on the caller's line.
struct LocalLine {
    Vec3d origin, direction;
    double shift;
};

LocalLine local_line(const Frustum& f, const Vec3d& origin, const Vec3d& direction) {
    const Vec3d middle = f.origin + f.axis * (0.5 * f.height);
    const double shift = dot(middle - origin, direction) / dot(direction, direction);
    return {f.local_point(origin + direction * shift), f.local_vector(direction), shift};
}

// g(t) = x² + y² − R(z)² along the line, negative inside the double cone (or the cylinder), and dg/dt.
double side_value(const Frustum& f, const LocalLine& line, double t, double& derivative) {
    const Vec3d p = line.origin + line.direction * t;
    const double r = f.radius_at(p.z);
    derivative = 2 * (p.x * line.direction.x + p.y * line.direction.y - f.slope() * line.direction.z * r);
    return p.x * p.x + p.y * p.y - r * r;
}

// Newton steps on g itself, which the expanded quadratic's coefficients approximate with cancellation for lines
// that nearly graze the side or nearly follow the axis. A step is kept only while it shrinks |g| and stays within
// `max_step` (less than the distance to the other root, so that it cannot jump there).
double polish(const Frustum& f, const LocalLine& line, double t, double max_step) {
    for (int step = 0; step < 2; ++step) {
        double derivative, ignored;
        const double value = side_value(f, line, t, derivative);
        if (value == 0 || derivative == 0) break;
        const double next = t - value / derivative;
        if (!(std::abs(next - t) <= max_step) || !(std::abs(side_value(f, line, next, ignored)) < std::abs(value))) break;
        t = next;
    }
    return t;
}

}  // namespace

FrustumCrossings frustum_crossings(const Frustum& f, const Vec3d& origin, const Vec3d& direction) {
    const LocalLine line = local_line(f, origin, direction);
    const Vec3d& o = line.origin;
    const Vec3d& d = line.direction;
    const double k = f.slope(), r0 = f.radius_at(o.z);
    const double a = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
    const double b = 2 * (o.x * d.x + o.y * d.y - k * d.z * r0);
    const double c = o.x * o.x + o.y * o.y - r0 * r0;
    QuadraticRoots roots = quadratic_roots(a, b, c);
    if (roots.count == 2) {
        const double max_step = 0.25 * (roots.roots[1] - roots.roots[0]);
        for (double& t : roots.roots) t = polish(f, line, t, max_step);
    }
    FrustumCrossings result;
    if (!f.caps) {
        if (a != 0 && roots.count < 2) return result;  // a double root: the line touches the side
        for (int i = 0; i < roots.count; ++i) {
            const double z = o.z + d.z * roots.roots[i];
            if (0 <= z && z <= f.height) result.crossing[result.count++] = {roots.roots[i] + line.shift, FrustumPart::Side};
        }
        return result;
    }
    // The solid is the double cone's inside cut by the slab 0 < z < height, where only one nappe lies.
    double slab_lo = -kInfinity, slab_hi = kInfinity;
    FrustumPart lo_part = FrustumPart::Side, hi_part = FrustumPart::Side;
    if (d.z == 0) {
        if (!(0 < o.z && o.z < f.height)) return result;
    } else {
        const double t_base = -o.z / d.z, t_top = (f.height - o.z) / d.z;
        const bool upwards = d.z > 0;
        slab_lo = upwards ? t_base : t_top;
        slab_hi = upwards ? t_top : t_base;
        lo_part = upwards ? FrustumPart::Base : FrustumPart::Top;
        hi_part = upwards ? FrustumPart::Top : FrustumPart::Base;
    }
    std::array<NegativePiece, 2> pieces;
    const int piece_count = negative_pieces(a, b, c, roots, pieces);
    // The frustum is convex, so at most one piece meets the slab (the other lies on the far nappe); should rounding
    // leave a sliver of the other, the longer one is the solid.
    double best_length = 0;
    for (int i = 0; i < piece_count; ++i) {
        const bool cut_below = pieces[i].lo <= slab_lo, cut_above = pieces[i].hi >= slab_hi;
        const double enter = cut_below ? slab_lo : pieces[i].lo, exit = cut_above ? slab_hi : pieces[i].hi;
        if (!(enter < exit) || !std::isfinite(exit - enter) || !(exit - enter > best_length)) continue;
        best_length = exit - enter;
        result.count = 2;
        result.crossing[0] = {enter + line.shift, cut_below ? lo_part : FrustumPart::Side};
        result.crossing[1] = {exit + line.shift, cut_above ? hi_part : FrustumPart::Side};
    }
    return result;
}

Vec3d frustum_normal(const Frustum& f, FrustumPart part, const Vec3d& p) {
    if (part == FrustumPart::Base) return -f.axis;
    if (part == FrustumPart::Top) return f.axis;
    const Vec3d q = f.local_point(p);
    const double rho = std::hypot(q.x, q.y), k = f.slope();
    if (!(rho > 0)) return f.top_radius < f.base_radius ? f.axis : -f.axis;  // the apex
    return normalize(f.world_vector(Vec3d(q.x / rho, q.y / rho, -k)));
}

void frustum_bounds(const Frustum& f, Vec3d& lower, Vec3d& upper) {
    const Vec3d reach = f.circle_reach();
    const Vec3d top = f.origin + f.axis * f.height;
    lower = min(f.origin - reach * f.base_radius, top - reach * f.top_radius);
    upper = max(f.origin + reach * f.base_radius, top + reach * f.top_radius);
}

}  // namespace isotrace
