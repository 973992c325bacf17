#include "geometry/superquadric/taper.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace isotrace {

Taper::Taper(double x_rate, double y_rate, double half_height)
    : x_rate_(x_rate), y_rate_(y_rate), half_height_(half_height) {}

Vec3d Taper::forward(const Vec3d& p) const { return {scale(x_rate_, p.z) * p.x, scale(y_rate_, p.z) * p.y, p.z}; }

Vec3d Taper::inverse(const Vec3d& q) const { return {q.x / scale(x_rate_, q.z), q.y / scale(y_rate_, q.z), q.z}; }

Jacobian Taper::jacobian(const Vec3d& p) const {
    const double slope = 1 / (2 * half_height_);
    return {{{scale(x_rate_, p.z), 0, 0},
             {0, scale(y_rate_, p.z), 0},
             {x_rate_ * slope * p.x, y_rate_ * slope * p.y, 1}}};
}

IntervalBox Taper::forward_box(const IntervalBox& box) const {
    return {box.x * scale(x_rate_, box.z), box.y * scale(y_rate_, box.z), box.z};
}

IntervalBox Taper::inverse_box(const IntervalBox& box) const {
    return {divide_by_positive(box.x, scale(x_rate_, box.z)), divide_by_positive(box.y, scale(y_rate_, box.z)), box.z};
}

// x = X·f(z) with z = Z, so dx = (dX − x·f'(z)·dZ)/f(z), and likewise for y.
IntervalBox Taper::inverse_tangent(const IntervalBox& preimage, const IntervalBox& tangent) const {
    const double dz_slope = 1 / (2 * half_height_);
    return {divide_by_positive(tangent.x - preimage.x * tangent.z * (x_rate_ * dz_slope), scale(x_rate_, preimage.z)),
            divide_by_positive(tangent.y - preimage.y * tangent.z * (y_rate_ * dz_slope), scale(y_rate_, preimage.z)),
            tangent.z};
}

std::optional<ConeAboutZ> Taper::carry(const ConeAboutZ& cone) const {
    if (cone.beta != 0) return std::nullopt;
    // α·(1 + r·(z + h)/(2h)) for the larger rate r: α + β·z.
    const double rate = std::max(x_rate_, y_rate_);
    return ConeAboutZ{cone.kx, cone.ky, cone.alpha * (1 + rate / 2), cone.alpha * rate / (2 * half_height_)};
}

std::string Taper::problem(const IntervalBox& input) const {
    for (const double rate : {x_rate_, y_rate_}) {
        const Interval s = scale(rate, input.z);
        if (s.lo >= kMinScale) continue;
        const double z = scale(rate, input.z.lo) < scale(rate, input.z.hi) ? input.z.lo : input.z.hi;
        std::ostringstream message;
        message << "taper: the cross-section scale falls to " << s.lo << " at z = " << z << "; it must stay >= "
                << kMinScale << " over the object";
        return message.str();
    }
    return {};
}

// With one rate for x and y, {G ≤ s} holds the points whose cross-section coordinates satisfy ‖(X/a1, Y/a2)‖_p2 ≤
// φ(z) = f(z)·s·r(z/(s·a3)), r(u) = (1 − |u|^p1)^(1/p1) the profile: a norm (convex) below φ, a convex set where φ is
// concave. (With two rates the cross-sections change their shape with the height, and some such sets are not convex.)
// In w = z/(s·a3), f = α + β·w with α = 1 + rate/2 (the scale at the centre) and β = rate·s/2; (α + β·w)·r(w) is
// concave on the side where the scale falls (the other side holds for any β) where (α − |β|·u)(p1 − 1) ≥
// 2|β|·u·(1 − u^p1) for u ∈ [0, 1], which holds where (α − |β|)(p1 − 1) ≥ 2|β|·m with m = max u·(1 − u^p1) =
// p1/(p1 + 1)·(p1 + 1)^(−1/p1): s ≤ α(p1 − 1) / (½|rate|·(p1 − 1 + 2m)). That also keeps the scale positive there.
double Taper::convex_levels(double p1) const {
    if (x_rate_ != y_rate_) return 0;
    if (x_rate_ == 0) return std::numeric_limits<double>::infinity();
    const double alpha = 1 + x_rate_ / 2, m = p1 / (p1 + 1) * std::pow(p1 + 1, -1 / p1);
    return alpha * (p1 - 1) / (std::abs(x_rate_) / 2 * (p1 - 1 + 2 * m)) * (1 - 1e-9);  // below, for its rounding
}

}  // namespace isotrace
