#include "geometry/superquadric/twist.h"

#include <cmath>

namespace isotrace {

// `at` is θ(p.z)'s: the columns are the turn's, and the turn's rate per height moves q = forward(p) by rate·(−y, x).
Jacobian Twist::jacobian_at(const Vec3d& p, SinCos at) const {
    const Vec3d q = turned(p, at);
    return {{{at.cos, at.sin, 0}, {-at.sin, at.cos, 0}, {-rate_ * q.y, rate_ * q.x, 1}}};
}

// The inverse turns q by φ = −θ(z), and φ changes with z at −rate: the turned tangent plus the point's own
// rotation rate·dz·(y, −x) (x, y the inverse point).
IntervalBox Twist::inverse_tangent(const IntervalBox& preimage, const IntervalBox& tangent) const {
    const Interval phi = Interval::spanning(-angle(preimage.z.lo), -angle(preimage.z.hi));
    const auto [s, c] = centred_sin_cos_range(phi);
    const Interval turn = tangent.z * rate_;
    return {tangent.x * c - tangent.y * s + turn * preimage.y, tangent.x * s + tangent.y * c - turn * preimage.x,
            tangent.z};
}

IntervalBox Twist::rotate_box(const IntervalBox& box, double sign) const {
    const Interval theta = Interval::spanning(sign * angle(box.z.lo), sign * angle(box.z.hi));
    const auto [s, c] = centred_sin_cos_range(theta);
    // The corners' farthest distance from the axis, √(a² + b²) widened by more than its rounding (and by 2⁻⁵⁰⁰ for
    // squares that underflow): hypot's care for overflow costs a call.
    const double a = std::max(-box.x.lo, box.x.hi), b = std::max(-box.y.lo, box.y.hi);
    const double reach = std::sqrt(a * a + b * b) * (1 + 0x1p-50) + 0x1p-500;
    const auto within_reach = [reach](Interval v) {
        return Interval{std::max(v.lo, -reach), std::min(v.hi, reach)};
    };
    return {within_reach(box.x * c - box.y * s), within_reach(box.x * s + box.y * c), box.z};
}

}  // namespace isotrace
