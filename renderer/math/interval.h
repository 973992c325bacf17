#pragma once
// Closed intervals of doubles and their arithmetic (Moore, "Interval Analysis"), so that the range of a function
// over a box or a stretch of ray can be bounded: the superquadrics' inverse deformations, implicit fields.
// Computed in round-to-nearest: a bound may be off by a few ulps, which can only matter for contacts at the
// rounding level (see docs/decisions.md).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "renderer/math/sin_cos.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct Interval {
    double lo = 0, hi = 0;

    static Interval point(double v) { return {v, v}; }
    static Interval unbounded() {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    }
    static Interval spanning(double a, double b) { return {std::min(a, b), std::max(a, b)}; }
    bool contains(double v) const { return lo <= v && v <= hi; }
    double width() const { return hi - lo; }
    bool is_finite() const { return std::isfinite(lo) && std::isfinite(hi); }
    // Every value has the same strict sign (a function whose derivative lies here is strictly monotone).
    bool excludes_zero() const { return lo > 0 || hi < 0; }
    // The interval of |v| for v in this interval.
    Interval magnitude() const {
        if (lo >= 0) return *this;
        if (hi <= 0) return {-hi, -lo};
        return {0, std::max(-lo, hi)};
    }
};

inline Interval operator+(Interval a, Interval b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline Interval operator-(Interval a, Interval b) { return {a.lo - b.hi, a.hi - b.lo}; }
inline Interval operator+(Interval a, double b) { return {a.lo + b, a.hi + b}; }
inline Interval operator-(Interval a) { return {-a.hi, -a.lo}; }
inline Interval operator*(Interval a, Interval b) {
    double p[] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    // An infinite end times a zero end is NaN in IEEE arithmetic, but the ends bound real numbers, so the product
    // of those ends is 0 (only unbounded intervals get here, so bounded ones pay one test).
    if (std::isnan(p[0] + p[1] + p[2] + p[3])) {
        const auto times = [](double u, double v) { return u == 0 || v == 0 ? 0.0 : u * v; };
        p[0] = times(a.lo, b.lo), p[1] = times(a.lo, b.hi), p[2] = times(a.hi, b.lo), p[3] = times(a.hi, b.hi);
    }
    return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
inline Interval operator*(Interval a, double s) {
    const double lo = a.lo * s, hi = a.hi * s;
    if (std::isnan(lo + hi)) return a * Interval::point(s);  // an infinite end times 0: the product's rule
    return Interval::spanning(lo, hi);
}
// Requires b.lo > 0 (the callers divide by strictly positive taper factors).
inline Interval divide_by_positive(Interval a, Interval b) {
    return {a.lo >= 0 ? a.lo / b.hi : a.lo / b.lo, a.hi >= 0 ? a.hi / b.lo : a.hi / b.hi};
}

// The smallest interval holding both.
inline Interval hull(Interval a, Interval b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }
inline Interval min(Interval a, Interval b) { return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)}; }
inline Interval max(Interval a, Interval b) { return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)}; }
inline Interval square(Interval a) {
    const Interval m = a.magnitude();
    return {m.lo * m.lo, m.hi * m.hi};
}
// a^n for an integer n ≥ 1: monotone for odd n, a function of |a| for even n.
inline Interval pow_int(Interval a, int n) {
    if (n % 2 == 0) a = a.magnitude();
    return {std::pow(a.lo, n), std::pow(a.hi, n)};
}
// The interval of 1/b; all the reals when b holds 0 (and the ends do not bound 1/b).
inline Interval reciprocal(Interval b) {
    if (b.lo > 0 || b.hi < 0) return {1 / b.hi, 1 / b.lo};
    return Interval::unbounded();
}
// Monotone functions: the function of the ends.
inline Interval exp(Interval a) { return {std::exp(a.lo), std::exp(a.hi)}; }
inline Interval atan(Interval a) { return {std::atan(a.lo), std::atan(a.hi)}; }
// √max(a, 0): the square root of the part of a that is not negative (0 for the rest).
inline Interval sqrt_of_non_negative(Interval a) {
    return {std::sqrt(std::max(a.lo, 0.0)), std::sqrt(std::max(a.hi, 0.0))};
}
// log max(a, floor) for a floor > 0.
inline Interval log_above(Interval a, double floor) {
    return {std::log(std::max(a.lo, floor)), std::log(std::max(a.hi, floor))};
}
// The signs of the values: ±1, both where a holds 0.
inline Interval sign_range(Interval a) {
    if (a.lo > 0) return {1, 1};
    if (a.hi < 0) return {-1, -1};
    return {-1, 1};
}

namespace interval_detail {
// Range of f = cos or sin over [θlo, θhi] (no wider than 2π), whose values at the ends are f_lo and f_hi: those,
// widened to ±1 where an extremum lies inside (f(first_extremum + kπ) is +1 for even k, −1 for odd k).
inline Interval periodic_range(Interval angle, double f_lo, double f_hi, double first_extremum) {
    constexpr double pi = std::numbers::pi;
    Interval r = Interval::spanning(f_lo, f_hi);
    for (double k = std::ceil((angle.lo - first_extremum) / pi); first_extremum + k * pi <= angle.hi; ++k) {
        if (std::fmod(std::abs(k), 2.0) == 0) r.hi = 1;
        else r.lo = -1;
    }
    return r;
}
// Beyond this magnitude doubles are spaced so widely that an angle's few ulps of rounding may span a period, and
// counting extrema by k·π would no longer advance k (a hang): such angles are treated as covering one.
constexpr double kLargestResolvedAngle = 0x1p50;
inline bool resolves(Interval angle) {
    return std::abs(angle.lo) < kLargestResolvedAngle && std::abs(angle.hi) < kLargestResolvedAngle;
}
// Also true for an unbounded angle, and for one too large to resolve.
inline bool covers_a_period(Interval angle) { return !(angle.width() < 2 * std::numbers::pi) || !resolves(angle); }
}  // namespace interval_detail

inline Interval cos_range(Interval angle) {
    if (interval_detail::covers_a_period(angle)) return {-1, 1};
    return interval_detail::periodic_range(angle, std::cos(angle.lo), std::cos(angle.hi), 0);
}

// The sine's own values at the ends, not the cosine of θ − π/2: that difference rounds to the ulp of π/2, which
// loses the relative precision of a small sine, and a slight bend divides its sine by the curvature (an identity
// bend, k = 10⁻¹², lost 5·10⁻⁵ of its object's bottom face from its bounds: a regression test).
inline Interval sin_range(Interval angle) {
    if (interval_detail::covers_a_period(angle)) return {-1, 1};
    return interval_detail::periodic_range(angle, std::sin(angle.lo), std::sin(angle.hi), std::numbers::pi / 2);
}

// sin_range and cos_range of one angle at the cost of one sincos per end (glibc's sincos returns sin's and cos's
// own values, so both ranges are exactly those of the two functions).
struct SinCosRange {
    Interval sin, cos;
};
// The same from the ends' sines and cosines, for callers that need those values too.
inline SinCosRange sin_cos_range(Interval angle, SinCos at_lo, SinCos at_hi) {
    if (interval_detail::covers_a_period(angle)) return {{-1, 1}, {-1, 1}};
    return {interval_detail::periodic_range(angle, at_lo.sin, at_hi.sin, std::numbers::pi / 2),
            interval_detail::periodic_range(angle, at_lo.cos, at_hi.cos, 0)};
}
inline SinCosRange sin_cos_range(Interval angle) {
    if (interval_detail::covers_a_period(angle)) return {{-1, 1}, {-1, 1}};
    return sin_cos_range(angle, sin_cos(angle.lo), sin_cos(angle.hi));
}

// sin and cos over an angle interval, holding their computed values at every point of it: over a narrow one
// [m − r, m + r] from one sincos at the midpoint by Taylor's theorem, sin(m + h) = sin m + h cos m − (h²/2) sin ξ
// with sin ξ within r of sin m (and the same for cos), which is within r²/2 of the exact range; wider ones take
// the values at both ends (sin_cos_range). The narrow enclosure is widened by kSinCosSlack for the rounding of the
// midpoint's sincos and of the arithmetic.
namespace interval_detail {
constexpr double kNarrowSinCos = 0.25;
constexpr double kSinCosSlack = 0x1p-50;
inline Interval taylor_range(double f, double f_prime, double r, double q) {
    const double lo = f - r * std::abs(f_prime) - q * std::max(std::min(f + r, 1.0), 0.0) - kSinCosSlack;
    const double hi = f + r * std::abs(f_prime) - q * std::min(std::max(f - r, -1.0), 0.0) + kSinCosSlack;
    return {std::max(lo, -1.0), std::min(hi, 1.0)};
}
}  // namespace interval_detail
inline SinCosRange centred_sin_cos_range(Interval a) {
    const double r = 0.5 * (a.hi - a.lo);
    if (!(r <= interval_detail::kNarrowSinCos) || !(std::abs(a.lo) < 0x1p50)) return sin_cos_range(a);
    const double m = a.lo + r;
    const double radius = std::max(m - a.lo, a.hi - m);
    const SinCos at_m = sin_cos(m);
    const double q = 0.5 * radius * radius;
    return {interval_detail::taylor_range(at_m.sin, at_m.cos, radius, q),
            interval_detail::taylor_range(at_m.cos, -at_m.sin, radius, q)};
}

struct IntervalBox {
    Interval x, y, z;

    static IntervalBox point(const Vec3d& p) { return {Interval::point(p.x), Interval::point(p.y), Interval::point(p.z)}; }
    Interval& operator[](int k) { return k == 0 ? x : (k == 1 ? y : z); }
    const Interval& operator[](int k) const { return k == 0 ? x : (k == 1 ? y : z); }
    Vec3d lower() const { return {x.lo, y.lo, z.lo}; }
    Vec3d upper() const { return {x.hi, y.hi, z.hi}; }
    bool is_finite() const { return x.is_finite() && y.is_finite() && z.is_finite(); }
    // The box of |x|, |y|, |z| for the points of this one.
    IntervalBox magnitude() const { return {x.magnitude(), y.magnitude(), z.magnitude()}; }
    bool contains(const Vec3d& p) const { return x.contains(p.x) && y.contains(p.y) && z.contains(p.z); }
    // The point of the box nearest p (p itself when the box contains it).
    Vec3d nearest(const Vec3d& p) const {
        return {std::clamp(p.x, x.lo, x.hi), std::clamp(p.y, y.lo, y.hi), std::clamp(p.z, z.lo, z.hi)};
    }
    void extend(const Vec3d& p) {
        for (int k = 0; k < 3; ++k) {
            (*this)[k].lo = std::min((*this)[k].lo, p[k]);
            (*this)[k].hi = std::max((*this)[k].hi, p[k]);
        }
    }
};

// The part of `box` inside `clip`; false when they do not overlap.
inline bool clip_box(IntervalBox& box, const IntervalBox& clip) {
    for (int k = 0; k < 3; ++k) {
        box[k].lo = std::max(box[k].lo, clip[k].lo);
        box[k].hi = std::min(box[k].hi, clip[k].hi);
        if (box[k].lo > box[k].hi) return false;
    }
    return true;
}

// tan over an angle interval: monotone between its poles π/2 + kπ, all the reals when one lies inside.
inline Interval tan_range(Interval angle) {
    constexpr double pi = std::numbers::pi;
    if (!interval_detail::resolves(angle) || !(angle.width() < pi)) return Interval::unbounded();
    const double first_pole = pi / 2 + std::ceil((angle.lo - pi / 2) / pi) * pi;
    if (first_pole <= angle.hi) return Interval::unbounded();
    return {std::tan(angle.lo), std::tan(angle.hi)};
}

// atan2(y, x) over a box: a box that holds the origin or meets the branch cut (x < 0, y = 0) may reach the whole
// [−π, π]; any other box is convex and on one continuous branch, where the angle, constant along rays from the
// origin, takes its extremes at the corners.
inline bool meets_atan2_cut(Interval y, Interval x) { return y.lo <= 0 && y.hi >= 0 && x.lo <= 0; }
inline Interval atan2_range(Interval y, Interval x) {
    constexpr double pi = std::numbers::pi;
    if (meets_atan2_cut(y, x)) return {-pi, pi};
    const double a[] = {std::atan2(y.lo, x.lo), std::atan2(y.lo, x.hi), std::atan2(y.hi, x.lo), std::atan2(y.hi, x.hi)};
    return {*std::min_element(a, a + 4), *std::max_element(a, a + 4)};
}

}  // namespace isotrace
