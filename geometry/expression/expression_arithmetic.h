#pragma once
// The number types an expression tape is evaluated in, and every operation of the tape on each:
//   double          the value;
//   Interval        an interval holding every value over a box;
//   PointGradient   the value and its gradient (forward-mode derivatives along x, y and z at once);
//   PointSlope      the value and its derivative along one direction (for Newton steps along a ray);
//   IntervalSlope   an interval of the value and one of its derivative along a direction, over a box;
//   IntervalGradient an interval of the value and one of each partial derivative, over a box (three
//                   IntervalSlope runs along the axes in one: each partial is computed as that run computes it).
// The domain rules of docs/expressions.md are defined here once for doubles and once for intervals (whose
// intervals hold every point value under the same rules); the derivative types apply the chain rule to them.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "renderer/math/interval.h"
#include "renderer/math/sin_cos.h"
#include "renderer/math/vec3.h"

namespace isotrace::expression_math {

using isotrace::sin_cos;  // of a double; the overloads below take intervals and duals

// log(a) for a below this is log of this (about −708): finite, and far below any value a surface is made of.
constexpr double kLogFloor = std::numeric_limits<double>::min();
constexpr double kLargest = std::numeric_limits<double>::max();

// ---- Doubles: the domain rules.
inline double sqrt(double a) { return std::sqrt(std::max(a, 0.0)); }
inline double sqrt_slope(double a) { return a > 0 ? 0.5 / std::sqrt(a) : 0; }
inline double log(double a) { return std::log(std::max(a, kLogFloor)); }
inline double log_slope(double a) { return a > kLogFloor ? 1 / a : 0; }
// x/0 = 0.
inline double inverse(double b) { return b == 0 ? 0 : 1 / b; }
inline double divide(double a, double b) { return b == 0 ? 0 : a / b; }
inline double exp(double a) { return std::exp(a); }
inline double sin(double a) { return std::sin(a); }
inline double cos(double a) { return std::cos(a); }
inline double tan(double a) { return std::tan(a); }
inline double atan(double a) { return std::atan(a); }
inline double atan2(double y, double x) { return std::atan2(y, x); }  // 0 at the origin
inline double abs(double a) { return std::abs(a); }
inline double sign(double a) { return a < 0 ? -1 : 1; }  // the right-hand slope of |a| at 0
inline double square(double a) { return a * a; }
inline double pow_int(double a, int n) { return std::pow(a, n); }
inline double min(double a, double b) { return std::min(a, b); }
inline double max(double a, double b) { return std::max(a, b); }
// Overflow stops at the largest double and NaN (which the rules leave no way to) reads 0, so nothing non-finite
// travels on through the tape.
inline double settle(double a) {
    if (std::abs(a) <= kLargest) [[likely]] return a;
    return a > 0 ? kLargest : (a < 0 ? -kLargest : 0.0);
}

// ---- Intervals: the same rules over a range (the operations without rules are those of interval.h).
inline Interval sqrt(Interval a) { return sqrt_of_non_negative(a); }
inline Interval sqrt_slope(Interval a) {
    if (a.hi <= 0) return {0, 0};
    if (a.lo > 0) return {0.5 / std::sqrt(a.hi), 0.5 / std::sqrt(a.lo)};
    return {0, std::numeric_limits<double>::infinity()};
}
inline Interval log(Interval a) { return log_above(a, kLogFloor); }
inline Interval log_slope(Interval a) {
    if (a.hi <= kLogFloor) return {0, 0};
    if (a.lo > kLogFloor) return {1 / a.hi, 1 / a.lo};
    return {0, 1 / kLogFloor};
}
inline Interval inverse(Interval b) {
    if (b.lo == 0 && b.hi == 0) return {0, 0};
    return reciprocal(b);  // all the reals when b holds 0, which holds the rule's 0 as well
}
inline Interval divide(Interval a, Interval b) { return a * inverse(b); }
inline Interval tan(Interval a) { return tan_range(a); }
inline Interval atan2(Interval y, Interval x) { return atan2_range(y, x); }
inline Interval abs(Interval a) { return a.magnitude(); }
inline Interval sign(Interval a) { return sign_range(a); }
// An end that came out NaN (∞ − ∞ of unbounded operands) bounds nothing: it becomes infinite. A lower end of +∞
// (or upper of −∞) comes down to the largest double, where the point values' overflow stops.
inline Interval settle(Interval a) {
    if (a.lo <= kLargest && a.hi >= -kLargest) [[likely]] return a;  // false for NaN ends too
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {std::isnan(a.lo) ? -inf : std::min(a.lo, kLargest), std::isnan(a.hi) ? inf : std::max(a.hi, -kLargest)};
}
inline Vec3d settle(const Vec3d& a) { return {settle(a.x), settle(a.y), settle(a.z)}; }

// Three intervals, the partial derivatives' bounds of an IntervalGradient: each operation acts on each alone.
struct IntervalVec3 {
    Interval x, y, z;
};
inline IntervalVec3 operator+(const IntervalVec3& a, const IntervalVec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline IntervalVec3 operator-(const IntervalVec3& a, const IntervalVec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline IntervalVec3 operator-(const IntervalVec3& a) { return {-a.x, -a.y, -a.z}; }
inline IntervalVec3 operator*(const IntervalVec3& a, Interval b) { return {a.x * b, a.y * b, a.z * b}; }
inline IntervalVec3 hull(const IntervalVec3& a, const IntervalVec3& b) {
    return {hull(a.x, b.x), hull(a.y, b.y), hull(a.z, b.z)};
}
inline IntervalVec3 settle(const IntervalVec3& a) { return {settle(a.x), settle(a.y), settle(a.z)}; }

// A derivative that no bound holds: every component unbounded.
template <class D> D unbounded_derivative() {
    if constexpr (std::is_same_v<D, IntervalVec3>) return {Interval::unbounded(), Interval::unbounded(), Interval::unbounded()};
    else return Interval::unbounded();
}

// ---- Derivatives: a value and its derivative d (the gradient, or the slope along a direction).
template <class V, class D>
struct Dual {
    V v;
    D d;
};
using PointGradient = Dual<double, Vec3d>;
using PointSlope = Dual<double, double>;
using IntervalSlope = Dual<Interval, Interval>;
using IntervalGradient = Dual<Interval, IntervalVec3>;

template <class V, class D> Dual<V, D> operator+(const Dual<V, D>& a, const Dual<V, D>& b) { return {a.v + b.v, a.d + b.d}; }
template <class V, class D> Dual<V, D> operator-(const Dual<V, D>& a, const Dual<V, D>& b) { return {a.v - b.v, a.d - b.d}; }
template <class V, class D> Dual<V, D> operator-(const Dual<V, D>& a) { return {-a.v, -a.d}; }
template <class V, class D> Dual<V, D> operator*(const Dual<V, D>& a, const Dual<V, D>& b) {
    return {a.v * b.v, a.d * b.v + b.d * a.v};
}
// (a/b)′ = (a′ − (a/b) b′) / b, with the rule's x/0 = 0 for both.
template <class V, class D> Dual<V, D> divide(const Dual<V, D>& a, const Dual<V, D>& b) {
    const V q = divide(a.v, b.v);
    return {q, (a.d - b.d * q) * inverse(b.v)};
}
template <class V, class D> Dual<V, D> square(const Dual<V, D>& a) { return {square(a.v), a.d * (a.v * 2.0)}; }
template <class V, class D> Dual<V, D> pow_int(const Dual<V, D>& a, int n) {
    return {pow_int(a.v, n), a.d * (pow_int(a.v, n - 1) * static_cast<double>(n))};
}
template <class V, class D> Dual<V, D> sqrt(const Dual<V, D>& a) { return {sqrt(a.v), a.d * sqrt_slope(a.v)}; }
template <class V, class D> Dual<V, D> exp(const Dual<V, D>& a) {
    const V e = exp(a.v);
    return {e, a.d * e};
}
template <class V, class D> Dual<V, D> log(const Dual<V, D>& a) { return {log(a.v), a.d * log_slope(a.v)}; }
inline SinCosRange sin_cos(Interval a) { return centred_sin_cos_range(a); }
inline Interval sin(Interval a) { return sin_cos(a).sin; }
inline Interval cos(Interval a) { return sin_cos(a).cos; }
template <class V, class D> struct DualSinCos {
    Dual<V, D> sin, cos;
};
template <class V, class D> DualSinCos<V, D> sin_cos(const Dual<V, D>& a) {
    const auto both = sin_cos(a.v);
    return {{both.sin, a.d * both.cos}, {both.cos, a.d * -both.sin}};
}
template <class V, class D> Dual<V, D> sin(const Dual<V, D>& a) { return sin_cos(a).sin; }
template <class V, class D> Dual<V, D> cos(const Dual<V, D>& a) { return sin_cos(a).cos; }
// Across a pole tan jumps from +∞ to −∞: its slope is then unbounded both ways (1 + tan² alone would claim it
// increases, hiding a root beyond the pole from a search that trusts monotonicity).
template <class V, class D> Dual<V, D> tan(const Dual<V, D>& a) {
    const V t = tan(a.v);
    if constexpr (std::is_same_v<V, Interval>)
        if (!t.is_finite()) return {t, unbounded_derivative<D>()};
    return {t, a.d * (square(t) + 1.0)};
}
template <class V, class D> Dual<V, D> atan(const Dual<V, D>& a) {
    return {atan(a.v), a.d * inverse(square(a.v) + 1.0)};
}
// atan2(y, x)′ = (x y′ − y x′) / (x² + y²), 0 at the origin by the division rule. Over a box that meets the
// branch cut the angle jumps by 2π, which no slope bounds: a finite one would let a search call the stretch
// monotone across the jump.
template <class V, class D> Dual<V, D> atan2(const Dual<V, D>& y, const Dual<V, D>& x) {
    if constexpr (std::is_same_v<V, Interval>)
        if (meets_atan2_cut(y.v, x.v)) return {atan2(y.v, x.v), unbounded_derivative<D>()};
    return {atan2(y.v, x.v), (y.d * x.v - x.d * y.v) * inverse(square(x.v) + square(y.v))};
}
template <class V, class D> Dual<V, D> abs(const Dual<V, D>& a) { return {abs(a.v), a.d * sign(a.v)}; }

// min and max take the derivative of the operand they select; over a box where either may be selected, both.
template <class D> Dual<double, D> min(const Dual<double, D>& a, const Dual<double, D>& b) { return a.v <= b.v ? a : b; }
template <class D> Dual<double, D> max(const Dual<double, D>& a, const Dual<double, D>& b) { return a.v >= b.v ? a : b; }
template <class D> Dual<Interval, D> min(const Dual<Interval, D>& a, const Dual<Interval, D>& b) {
    if (a.v.hi <= b.v.lo) return a;
    if (b.v.hi <= a.v.lo) return b;
    return {min(a.v, b.v), hull(a.d, b.d)};
}
template <class D> Dual<Interval, D> max(const Dual<Interval, D>& a, const Dual<Interval, D>& b) {
    if (a.v.lo >= b.v.hi) return a;
    if (b.v.lo >= a.v.hi) return b;
    return {max(a.v, b.v), hull(a.d, b.d)};
}
template <class V, class D> Dual<V, D> settle(const Dual<V, D>& a) { return {settle(a.v), settle(a.d)}; }

}  // namespace isotrace::expression_math
