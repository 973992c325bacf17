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

// x = R(φ)·q in the xy plane with φ′ = −rate·q′z: x′ = R·q′ + φ′·J·x (J turns by 90°), and since R and J commute,
// x″ = R·q″ + 2φ′·J·x′ + φ′²·x + φ″·J·x.
IntervalBox Twist::inverse_curvature(const IntervalBox& preimage, const IntervalBox& tangent,
                                     const IntervalBox& curvature, const IntervalBox& inverse_tangent) const {
    const Interval turn = tangent.z * -rate_, turn_rate = curvature.z * -rate_, twice = turn * 2.0, turn_squared = square(turn);
    Interval x = twice * -inverse_tangent.y + turn_squared * preimage.x + turn_rate * -preimage.y;
    Interval y = twice * inverse_tangent.x + turn_squared * preimage.y + turn_rate * preimage.x;
    const bool straight = curvature.x.lo == 0 && curvature.x.hi == 0 && curvature.y.lo == 0 && curvature.y.hi == 0;
    if (!straight) {  // the ray itself (the last stage's q″ = 0) needs no turn
        const Interval phi = Interval::spanning(-angle(preimage.z.lo), -angle(preimage.z.hi));
        const auto [s, c] = centred_sin_cos_range(phi);
        x = x + (curvature.x * c - curvature.y * s);
        y = y + (curvature.x * s + curvature.y * c);
    }
    return {x, y, curvature.z};
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
