#include "geometry/superquadric/twist.h"

#include <cmath>

#include "renderer/math/sin_cos.h"

namespace isotrace {

Vec3d Twist::rotate(const Vec3d& p, double theta) {
    const auto [s, c] = sin_cos(theta);
    return {p.x * c - p.y * s, p.x * s + p.y * c, p.z};
}

Jacobian Twist::jacobian(const Vec3d& p) const {
    const double theta = angle(p.z);
    const auto [s, c] = sin_cos(theta);
    const Vec3d q = rotate(p, theta);
    return {{{c, s, 0}, {-s, c, 0}, {-rate_ * q.y, rate_ * q.x, 1}}};
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
