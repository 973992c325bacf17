#pragma once
// Closed intervals of doubles and their arithmetic (Moore, "Interval Analysis"), so that the range of a function
// over a box or a stretch of ray can be bounded: the superquadrics' inverse deformations, implicit fields.
// Computed in round-to-nearest: a bound may be off by a few ulps, which can only matter for contacts at the
// rounding level (see docs/decisions.md).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

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
inline Interval operator*(Interval a, double s) { return Interval::spanning(a.lo * s, a.hi * s); }
inline Interval operator*(Interval a, Interval b) {
    const double p[] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
// Requires b.lo > 0 (the callers divide by strictly positive taper factors).
inline Interval divide_by_positive(Interval a, Interval b) {
    return {a.lo >= 0 ? a.lo / b.hi : a.lo / b.lo, a.hi >= 0 ? a.hi / b.lo : a.hi / b.hi};
}

namespace interval_detail {
// Range of f = cos or sin over [θlo, θhi]: the values at the ends, widened to ±1 where an extremum lies inside
// (f(first_extremum + kπ) is +1 for even k, −1 for odd k).
template <class F>
Interval periodic_range(Interval angle, F f, double first_extremum) {
    constexpr double pi = std::numbers::pi;
    if (angle.width() >= 2 * pi) return {-1, 1};
    Interval r = Interval::spanning(f(angle.lo), f(angle.hi));
    for (double k = std::ceil((angle.lo - first_extremum) / pi); first_extremum + k * pi <= angle.hi; ++k) {
        if (std::fmod(std::abs(k), 2.0) == 0) r.hi = 1;
        else r.lo = -1;
    }
    return r;
}
}  // namespace interval_detail

inline Interval cos_range(Interval angle) {
    return interval_detail::periodic_range(angle, [](double a) { return std::cos(a); }, 0);
}

// The sine's own values at the ends, not the cosine of θ − π/2: that difference rounds to the ulp of π/2, which
// loses the relative precision of a small sine, and a slight bend divides its sine by the curvature (an identity
// bend, k = 10⁻¹², lost 5·10⁻⁵ of its object's bottom face from its bounds: a regression test).
inline Interval sin_range(Interval angle) {
    return interval_detail::periodic_range(angle, [](double a) { return std::sin(a); }, std::numbers::pi / 2);
}

struct IntervalBox {
    Interval x, y, z;

    static IntervalBox point(const Vec3d& p) { return {Interval::point(p.x), Interval::point(p.y), Interval::point(p.z)}; }
    Interval& operator[](int k) { return k == 0 ? x : (k == 1 ? y : z); }
    const Interval& operator[](int k) const { return k == 0 ? x : (k == 1 ? y : z); }
    Vec3d lower() const { return {x.lo, y.lo, z.lo}; }
    Vec3d upper() const { return {x.hi, y.hi, z.hi}; }
    bool contains(const Vec3d& p) const { return x.contains(p.x) && y.contains(p.y) && z.contains(p.z); }
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

}  // namespace isotrace
