#include "geometry/torus/torus.h"

#include <algorithm>
#include <cmath>

#include "geometry/polynomial/monotone_root_finder.h"

namespace isotrace {
namespace {

// The line in the torus's frame and in units of the major radius, p(s) = origin + s·direction with a unit
// direction and the origin at the point nearest the centre; the caller's t is (s + shift) / scale.
struct UnitLine {
    Vec3d origin, direction;
    double shift, scale;
};

UnitLine unit_line(const Torus& torus, const Vec3d& origin, const Vec3d& direction) {
    const Vec3d d = torus.local_vector(direction) / torus.major_radius;
    const double scale = length(d);
    const Vec3d u = d / scale;
    const Vec3d p = torus.local_point(origin) / torus.major_radius;
    const double shift = -dot(p, u);
    return {p + u * shift, u, shift, scale};
}

// The signed distance to the tube in units of the major radius (r: the minor radius in those units) and its
// derivative along the unit line.
double unit_distance(const UnitLine& line, double r, double s, double& derivative) {
    const Vec3d p = line.origin + line.direction * s;
    // Plain square roots, not hypot (several times slower): in units of R near the torus nothing overflows.
    const double rho = std::sqrt(p.x * p.x + p.y * p.y), off = rho - 1, tube = std::sqrt(off * off + p.z * p.z);
    const double radial = rho > 0 ? (p.x * line.direction.x + p.y * line.direction.y) / rho : 0;
    derivative = tube > 0 ? (off * radial + p.z * line.direction.z) / tube : 0;
    return tube - r;
}

// Newton steps on the exact distance, whose value keeps full precision where the quartic's expanded coefficients
// cancel (thin tubes, r/R = 10⁻³, lose about six digits there). A step is kept while it shrinks the distance and
// stays small, so that it cannot leave the root the quartic bracketed for a neighbour.
double polish(const UnitLine& line, double r, double s) {
    const double max_step = 1e-6 * std::max(r, 1e-3);
    for (int step = 0; step < 2; ++step) {
        double derivative, ignored;
        const double value = unit_distance(line, r, s, derivative);
        if (value == 0 || derivative == 0) break;
        const double next = s - value / derivative;
        if (!(std::abs(next - s) <= max_step) || !(std::abs(unit_distance(line, r, next, ignored)) < std::abs(value)))
            break;
        s = next;
    }
    return s;
}

}  // namespace

TorusCrossings torus_crossings(const Torus& torus, const Vec3d& origin, const Vec3d& direction, double t_min,
                               double t_max, bool first_only) {
    TorusCrossings result;
    const UnitLine line = unit_line(torus, origin, direction);
    const double r = torus.minor_radius / torus.major_radius;
    const Vec3d& o = line.origin;
    const Vec3d& u = line.direction;
    // Only the chord inside the bounding sphere (radius 1 + r) can hold roots; a line that misses it costs no more.
    // Where the line grazes the outer equator the roots lie at the chord's very ends, which the subtraction below
    // rounds: the chord is widened by far more than that (1e-6 of R at a tangent line, less elsewhere).
    const double outer2 = (1 + r) * (1 + r), nearest2 = dot(o, o);
    if (!(nearest2 < outer2 * (1 + 1e-12))) return result;
    const double half_chord = std::sqrt(std::max(0.0, outer2 - nearest2) + 1e-12 * outer2);
    double lo = std::max(-half_chord, t_min * line.scale - line.shift);
    double hi = std::min(half_chord, t_max * line.scale - line.shift);
    // The torus also lies within the slab |z| ≤ r: for a thin tube this leaves a short stretch or none.
    const double slab = r * (1 + 1e-12) + 1e-15;
    if (u.z != 0) {
        const double a = (-slab - o.z) / u.z, b = (slab - o.z) / u.z;
        lo = std::max(lo, std::min(a, b));
        hi = std::min(hi, std::max(a, b));
    } else if (!(std::abs(o.z) <= slab)) {
        return result;
    }
    if (!(lo < hi)) return result;
    // (|p|² + 1 − r²)² − 4(x² + y²) along p = o + s·u with |u| = 1; β = 2 o·u is 0 but for rounding.
    const double beta = 2 * dot(o, u), gamma = nearest2 + 1 - r * r;
    const double radial_u = u.x * u.x + u.y * u.y, radial_ou = o.x * u.x + o.y * u.y, radial_o = o.x * o.x + o.y * o.y;
    const Polynomial quartic{gamma * gamma - 4 * radial_o, 2 * beta * gamma - 8 * radial_ou,
                             beta * beta + 2 * gamma - 4 * radial_u, 2 * beta, 1};
    // A root's polished t, kept when it lies strictly inside the range; a tangent contact is a miss (grazing).
    const auto add = [&](const PolynomialRoot& root) {
        if (root.tangent) return;
        const double t = (polish(line, r, root.t) + line.shift) / line.scale;
        if (!(t > t_min && t < t_max)) return;
        if (result.count > 0 && !(t > result.t[std::size_t(result.count - 1)])) return;
        result.t[std::size_t(result.count++)] = t;
    };
    // The first root alone is cheaper to find than all four; when it is no crossing, all of them are searched.
    if (first_only) {
        const std::optional<PolynomialRoot> first = first_root(quartic, lo, hi);
        if (!first) return result;
        add(*first);
        if (result.count > 0) return result;
    }
    for (const PolynomialRoot& root : all_roots(quartic, lo, hi)) {
        add(root);
        if (first_only && result.count > 0) break;
    }
    return result;
}

double torus_distance(const Torus& torus, const Vec3d& p) {
    const Vec3d q = torus.local_point(p);
    return std::hypot(std::hypot(q.x, q.y) - torus.major_radius, q.z) - torus.minor_radius;
}

Vec3d torus_gradient(const Torus& torus, const Vec3d& p) {
    const Vec3d q = torus.local_point(p);
    const double rho = std::hypot(q.x, q.y);
    const Vec3d radial = rho > 0 ? Vec3d(q.x / rho, q.y / rho, 0) : Vec3d(1, 0, 0);  // any on the axis
    const double off = rho - torus.major_radius, tube = std::hypot(off, q.z);
    if (!(tube > 0)) return torus.world_vector(radial);  // on the core circle
    return torus.world_vector(radial * (off / tube) + Vec3d(0, 0, q.z / tube));
}

void torus_bounds(const Torus& torus, Vec3d& lower, Vec3d& upper) {
    // The core circle's reach, and the tube's radius every way.
    const Vec3d extent = torus.circle_reach() * torus.major_radius + Vec3d(1, 1, 1) * torus.minor_radius;
    lower = torus.origin - extent;
    upper = torus.origin + extent;
}

}  // namespace isotrace
