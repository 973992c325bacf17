#include "geometry/superquadric/bend.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "renderer/math/sin_cos.h"

namespace isotrace {

Bend::Bend(double curvature, double direction, double centre, Interval region)
    : curvature_(curvature),
      centre_(centre),
      region_(region),
      angle_lo_(curvature * (region.lo - centre)),
      angle_hi_(curvature * (region.hi - centre)),
      angle_middle_(0.5 * (angle_lo_ + angle_hi_)),
      cos_middle_(std::cos(angle_middle_)),
      sin_middle_(std::sin(angle_middle_)),
      u_(std::cos(direction), std::sin(direction), 0),
      v_(-std::sin(direction), std::cos(direction), 0) {}

double Bend::region_angle(double z) const { return curvature_ * (std::clamp(z, region_.lo, region_.hi) - centre_); }

double Bend::beyond_region(double z) const { return z - std::clamp(z, region_.lo, region_.hi); }

// 1 − cos θ without cancellation: sin²θ/(1 + cos θ) where cos θ ≥ 0 (then 1 + cos θ ≥ 1), 1 − cos θ itself below
// (then it is at least 1).
double Bend::versine(SinCos at) { return at.cos >= 0 ? at.sin * at.sin / (1 + at.cos) : 1 - at.cos; }

// The formulas are arranged so that nothing of size R = 1/k is formed: R − (R − s)·cos θ becomes
// s·cos θ + (1 − cos θ)/k, and R·sin θ is sin θ/k (≈ z − z0), so a slight bend stays as exact as no bend.
Vec3d Bend::forward(const Vec3d& p) const {
    const double s = dot(p, u_), w = dot(p, v_);
    const double theta = region_angle(p.z);
    const double beyond = beyond_region(p.z);
    const SinCos at = sin_cos(theta);
    return from_frame(versine(at) / curvature_ + s * at.cos + beyond * at.sin, w,
                      centre_ + at.sin / curvature_ - s * at.sin + beyond * at.cos);
}

Vec3d Bend::inverse(const Vec3d& q) const {
    const double s_in = dot(q, u_), z_in = q.z - centre_;
    // The angle about the bend centre, (k·S − 1, k·(Z − z0)) scaled by k, relative to the region's middle angle.
    const double a = curvature_ * s_in - 1, b = curvature_ * z_in;
    const double cm = cos_middle_, sm = sin_middle_;
    const double relative = std::atan2(b * cm + a * sm, -a * cm + b * sm);
    const double unclamped = angle_middle_ + relative;
    const double theta = std::clamp(unclamped, angle_lo_, angle_hi_);
    // θ is the angle of (−a, b): where it is not clamped, its cosine and sine are that vector's, which takes a root
    // and two quotients that need not wait for the arctangent, where sincos would.
    const double rho = std::sqrt(a * a + b * b);
    const SinCos at = theta == unclamped && rho > 0 ? SinCos{b / rho, -a / rho} : sin_cos(theta);
    return from_frame(versine(at) / curvature_ + s_in * at.cos - z_in * at.sin, dot(q, v_),
                      centre_ + (theta - at.sin) / curvature_ + s_in * at.sin + z_in * at.cos);
}

Jacobian Bend::jacobian(const Vec3d& p) const {
    const auto [sn, c] = sin_cos(region_angle(p.z));
    const bool in_region = region_.contains(p.z);
    // Columns in the frame: ∂/∂s, ∂/∂w, ∂/∂z of (S, W, Z).
    const double along = in_region ? 1 - dot(p, u_) * curvature_ : 1;  // (R − s)·k
    const Vec3d d_ds = from_frame(c, 0, -sn), d_dw = v_, d_dz = from_frame(along * sn, 0, along * c);
    // ∂s/∂(x, y) = (u.x, u.y), ∂w/∂(x, y) = (v.x, v.y).
    return {{d_ds * u_.x + d_dw * v_.x, d_ds * u_.y + d_dw * v_.y, d_dz}};
}

// Inline: interval products the size of a call, on every box of a bent shape's walk.
[[gnu::always_inline]] inline Bend::FrameBox Bend::to_frame(const IntervalBox& box) const {
    return {box.x * u_.x + box.y * u_.y, box.x * v_.x + box.y * v_.y, box.z};
}

[[gnu::always_inline]] inline IntervalBox Bend::from_frame(const FrameBox& box) const {
    return {box.s * u_.x + box.w * v_.x, box.s * u_.y + box.w * v_.y, box.z};
}

// The versines at the ends, 0 where a multiple of 2π lies inside (cos reaches 1) and 2 where an odd multiple of π
// does (cos reaches −1).
Interval Bend::versine_over_curvature(SinCos at_lo, SinCos at_hi, Interval cos) const {
    const double v_lo = versine(at_lo), v_hi = versine(at_hi);
    return Interval{cos.hi == 1 ? 0 : std::min(v_lo, v_hi), cos.lo == -1 ? 2 : std::max(v_lo, v_hi)} * (1 / curvature_);
}

IntervalBox Bend::forward_box(const IntervalBox& box) const {
    const FrameBox f = to_frame(box);
    const Interval theta = {region_angle(f.z.lo), region_angle(f.z.hi)};
    const Interval beyond = {beyond_region(f.z.lo), beyond_region(f.z.hi)};  // non-decreasing in z
    const SinCos at_lo = sin_cos(theta.lo), at_hi = sin_cos(theta.hi);
    const auto [sn, c] = sin_cos_range(theta, at_lo, at_hi);
    return from_frame({versine_over_curvature(at_lo, at_hi, c) + f.s * c + beyond * sn, f.w,
                       sn * (1 / curvature_) - f.s * sn + beyond * c + centre_});
}

IntervalBox Bend::inverse_box(const IntervalBox& box) const {
    const FrameBox f = to_frame(box);
    const Interval z_in = f.z + (-centre_);
    const Interval a = f.s * curvature_ + (-1.0), b = z_in * curvature_;
    // The angles about the centre that the box covers, relative to the region's middle angle: those of its two
    // extreme corners, unless it contains the centre or straddles the opposite direction (then every angle). A
    // corner's direction from the centre is u = (−a, b) in the bend frame; a box that does not hold the centre lies
    // within half a turn of it, and the signs of its sides tell which corners turn least and most (atan2 is most
    // of the walk: two calls instead of one per corner).
    struct Direction {
        double x, y;
    };
    const double x0 = -a.hi, x1 = -a.lo, y0 = b.lo, y1 = b.hi;
    Direction first{}, last{};  // the most clockwise and the most counter-clockwise corner
    bool holds_centre = false;
    if (x0 > 0) first = {y0 >= 0 ? x1 : x0, y0}, last = {y1 >= 0 ? x0 : x1, y1};
    else if (x1 < 0) first = {y1 <= 0 ? x0 : x1, y1}, last = {y0 <= 0 ? x1 : x0, y0};
    else if (y0 > 0) first = {x1, x1 <= 0 ? y1 : y0}, last = {x0, x0 <= 0 ? y0 : y1};
    else if (y1 < 0) first = {x0, x0 >= 0 ? y0 : y1}, last = {x1, x1 >= 0 ? y1 : y0};
    else holds_centre = true;
    const double cm = cos_middle_, sm = sin_middle_;
    const auto relative_angle = [&](Direction u) { return std::atan2(u.y * cm - u.x * sm, u.x * cm + u.y * sm); };
    Interval relative{-std::numbers::pi, std::numbers::pi};
    if (!holds_centre) {
        const Interval spanned{relative_angle(first), relative_angle(last)};
        if (spanned.lo <= spanned.hi && spanned.width() < std::numbers::pi) relative = spanned;
    }
    const Interval unclamped = relative + angle_middle_;
    if (unclamped.lo >= angle_lo_ && unclamped.hi <= angle_hi_) {
        // Every point of the box turns about the centre within the region: its preimage is s = (1 − ρ)/k along the
        // bend direction and z = z0 + θ/k, with ρ its distance from the centre (in units of 1/k) and θ its angle. So
        // the ranges of ρ (nearest and farthest point) and θ over the box give the preimage's own bounding box,
        // without the wrapping of interval sines and cosines. (1 − ρ)/k is taken as (s·(2 − k·s) − k·z²)/(1 + ρ) at
        // those points, which forms nothing of size 1/k: a slight bend stays as exact as no bend.
        const auto undeformed_s = [&](double s, double z, double x, double y) {
            return (s * (2 - curvature_ * s) - curvature_ * z * z) / (1 + std::sqrt(x * x + y * y));
        };
        const bool near_x_inside = !(x0 > 0) && !(x1 < 0), near_y_inside = !(y0 > 0) && !(y1 < 0);
        const double near_s = near_x_inside ? 1 / curvature_ : x0 > 0 ? f.s.hi : f.s.lo;
        const double near_z = near_y_inside ? 0 : y0 > 0 ? z_in.lo : z_in.hi;
        const double near_x = near_x_inside ? 0 : x0 > 0 ? x0 : x1, near_y = near_y_inside ? 0 : y0 > 0 ? y0 : y1;
        const bool far_x0 = std::abs(x0) >= std::abs(x1), far_y0 = std::abs(y0) >= std::abs(y1);
        const double lowest = undeformed_s(far_x0 ? f.s.hi : f.s.lo, far_y0 ? z_in.lo : z_in.hi,
                                           far_x0 ? x0 : x1, far_y0 ? y0 : y1);
        const double highest = undeformed_s(near_s, near_z, near_x, near_y);
        return from_frame({{lowest, highest}, f.w, unclamped * (1 / curvature_) + centre_});
    }
    const Interval theta = {std::clamp(unclamped.lo, angle_lo_, angle_hi_),
                            std::clamp(unclamped.hi, angle_lo_, angle_hi_)};
    const SinCos at_lo = sin_cos(theta.lo), at_hi = sin_cos(theta.hi);
    const auto [sn, c] = sin_cos_range(theta, at_lo, at_hi);
    // θ − sin θ is non-decreasing.
    const Interval arc_excess = Interval{theta.lo - at_lo.sin, theta.hi - at_hi.sin} * (1 / curvature_);
    return from_frame({versine_over_curvature(at_lo, at_hi, c) + f.s * c - z_in * sn, f.w,
                       arc_excess + f.s * sn + z_in * c + centre_});
}

// In the bend frame the Jacobian is a rotation by θ times diag(1, 1, along) with along = 1 − k·s inside the region
// and 1 beyond it (see jacobian()), so its inverse is diag(1, 1, 1/along)·Rᵀ(θ).
IntervalBox Bend::inverse_tangent(const IntervalBox& preimage, const IntervalBox& tangent) const {
    const FrameBox p = to_frame(preimage), v = to_frame(tangent);
    const Interval theta = {region_angle(p.z.lo), region_angle(p.z.hi)};
    const auto [sn, c] = centred_sin_cos_range(theta);
    Interval along{1, 1};
    if (p.z.hi >= region_.lo && p.z.lo <= region_.hi) {
        const Interval bent = Interval{1, 1} - p.s * curvature_;
        const bool all_in_region = p.z.lo >= region_.lo && p.z.hi <= region_.hi;
        along = all_in_region ? bent : Interval{std::min(bent.lo, 1.0), std::max(bent.hi, 1.0)};
    }
    return from_frame({c * v.s - sn * v.z, v.w, divide_by_positive(sn * v.s + c * v.z, along)});
}

std::optional<BendSector> Bend::sector(const IntervalBox& before, Interval heights,
                                       const std::optional<ConeAboutZ>& cone) const {
    if (!(heights.lo >= region_.lo && heights.hi <= region_.hi)) return std::nullopt;
    Interval s = to_frame(before).s;
    if (cone) {  // the cone's widest cross-section, an ellipse, reaches this far along u
        const double widest = std::max(cone->radius_scale(heights.lo), cone->radius_scale(heights.hi));
        const double reach = widest * std::hypot(u_.x / cone->kx, u_.y / cone->ky);
        s = {std::max(s.lo, -reach), std::min(s.hi, reach)};
    }
    const SinCos lowest = sin_cos(region_angle(heights.lo)), highest = sin_cos(region_angle(heights.hi));
    return BendSector{u_, curvature_, centre_, 1 - curvature_ * s.hi, 1 - curvature_ * s.lo,
                      lowest.sin, lowest.cos, highest.sin, highest.cos};
}

std::string Bend::problem(const IntervalBox& input) const {
    std::ostringstream message;
    const double reach = to_frame(input).s.hi * curvature_;
    if (reach > kMaxCurvatureTimesExtent) {
        message << "bend: curvature times the object's extent toward the bend is " << reach
                << "; it must stay below " << kMaxCurvatureTimesExtent
                << " (the object would fold through the bend's centre, where the inverse is singular)";
        return message.str();
    }
    const double degrees = (angle_hi_ - angle_lo_) * 180 / std::numbers::pi;
    if (degrees > 180) {
        message << "bend: the region bends through " << degrees << " degrees; at most 180 are supported";
        return message.str();
    }
    return {};
}

}  // namespace isotrace
