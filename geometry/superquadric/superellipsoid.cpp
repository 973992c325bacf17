#include "geometry/superquadric/superellipsoid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geometry/superquadric/within_quadric.h"

namespace isotrace {
namespace {

// (a^p + b^p)^(1/p) for a, b ≥ 0 as larger·(1 + r^p)^(1/p) with r = smaller/larger, scaled by the larger so that
// neither overflows nor underflows matter; r, r^p, the sum 1 + r^p and its root kept for the partial derivatives.
// The Euclidean norm (p = 2, round cross-sections) is √(a² + b²) wherever the squares neither overflow nor lose
// digits to underflow: without the division, one step shorter on the gauge's critical path.
struct PNorm {
    double larger, smaller, ratio, power, sum, root, norm;
    bool euclidean = false;  // then ratio, power, sum and root are not taken
};

// Inlined into its callers: a call costs as much as the rest of a round p-norm. Without `partials` only the norm is
// wanted: where it has its own polynomial (NormExponent::tabulated_norm), r^p and 1 + r^p are not taken.
template <bool partials = true>
[[gnu::always_inline]] inline PNorm p_norm_parts(double a, double b, const NormExponent& p) {
    const double larger = std::max(a, b), smaller = std::min(a, b);
    if (larger == 0 || std::isinf(larger)) return {larger, smaller, 0, 0, 1, 1, larger};
    if (p.whole == 2 && larger > 0x1p-480 && larger < 0x1p480)
        return {larger, smaller, 0, 0, 0, 0, std::sqrt(a * a + b * b), true};
    const double ratio = smaller / larger;
    const bool tabulated = p.has_tabulated_norm(ratio);
    if (!partials && tabulated) {
        const double root = p.tabulated_norm(ratio);
        return {larger, smaller, ratio, NAN, NAN, root, larger * root};
    }
    const double power = p.unit_power(ratio), sum = 1 + power;
    // The root from the norm's own polynomial where there is one, as the norm alone takes it.
    const double root = tabulated ? p.tabulated_norm(ratio) : p.root(sum);
    return {larger, smaller, ratio, power, sum, root, larger * root};
}

// The p-norm's shares' powers p − 1 at a pair not both 0: (larger/N)^(p−1) = root/sum and (smaller/N)^(p−1) =
// r^(p−1)·root/sum, with r^(p−1) = r^p/r from r^p itself (not sum − 1, which keeps only its digits above 1's
// rounding: the normal needs them all); for the Euclidean norm larger/N and smaller/N. `vanishing`: the smaller's
// at r = 0. The divisions need no root: they run beside it, off the gauge's critical path.
std::pair<double, double> share_powers_at(const PNorm& n, double vanishing) {
    if (n.euclidean) {
        const double inverse = 1 / n.norm;
        return {n.larger * inverse, n.smaller * inverse};
    }
    const double of_larger = n.root * (1 / n.sum);
    return {of_larger, n.ratio > 0 ? n.power / n.ratio * of_larger : vanishing};
}

double p_norm(double a, double b, const NormExponent& p) { return p_norm_parts<false>(a, b, p).norm; }

// ∂‖(a, b)‖_p/∂a and ∂/∂b: (a/N)^(p−1). At a zero argument the limit: 0 for p > 1, 1 for p = 1, unbounded (NaN,
// so that no Newton step is taken) below.
std::pair<double, double> p_norm_partials(const PNorm& n, double a, double p) {
    if (n.larger == 0 || std::isinf(n.larger)) return {NAN, NAN};
    const auto [of_larger, of_smaller] = share_powers_at(n, p > 1 ? 0 : p == 1 ? 1 : NAN);
    return a >= n.smaller && a == n.larger ? std::pair{of_larger, of_smaller} : std::pair{of_smaller, of_larger};
}

// A 2-vector's p-norm lies between its Euclidean norm times these: 2^(1/p − 1/2) and 1 in the order of p and 2.
double euclidean_share(double p) { return std::min(1.0, std::exp2(1 / p - 0.5)); }
double euclidean_multiple(double p) { return std::max(1.0, std::exp2(1 / p - 0.5)); }

double signed_power(double base, double exponent) { return std::copysign(std::pow(std::abs(base), exponent), base); }

}  // namespace

Superellipsoid::Superellipsoid(const Vec3d& radii, double north_south, double east_west)
    : radii_(radii),
      inverse_radii_(1 / radii.x, 1 / radii.y, 1 / radii.z),
      north_south_(north_south),
      east_west_(east_west),
      p1_(NormExponent::of_epsilon(north_south)),
      p2_(NormExponent::of_epsilon(east_west)),
      log_radii_(std::log(radii.x), std::log(radii.y), std::log(radii.z)) {
    // h = ‖(u, v)‖_p2 ≥ c2·‖(u, v)‖₂ and G = ‖(h, w)‖_p1 ≥ max(h, c1·‖(h, w)‖₂): G ≤ 1 inside both quadrics.
    const double c1 = euclidean_share(p1_.p), c2 = euclidean_share(p2_.p);
    // And G ≤ C1·‖(C2·‖(u, v)‖₂, w)‖₂ the same way.
    const double m1 = euclidean_multiple(p1_.p), m2 = euclidean_multiple(p2_.p);
    const auto scales_of = [&](double across_x, double across_y) {
        return QuadricScales{{c2 / across_x, c2 / across_y, 0},
                             {c1 * c2 / across_x, c1 * c2 / across_y, c1 / radii.z},
                             {m1 * m2 / across_x, m1 * m2 / across_y, m1 / radii.z}};
    };
    along_radii_ = scales_of(radii.x, radii.y);
    // Round: (x² + y²)/max(a1, a2)² ≤ u² + v² ≤ (x² + y²)/min(a1, a2)², so the outer quadrics widen to the larger
    // radius and the inner one narrows to the smaller.
    const QuadricScales wide = scales_of(std::max(radii.x, radii.y), std::max(radii.x, radii.y)),
                        narrow = scales_of(std::min(radii.x, radii.y), std::min(radii.x, radii.y));
    round_about_z_ = {wide.cylinder, wide.ellipsoid, narrow.inscribed};
    enclosing_polytope_ = EnclosingPolytope(radii, p1_.p, p2_.p);
}

double Superellipsoid::gauge(const Vec3d& p) const {
    const Vec3d m = magnitudes(p);
    return p_norm(p_norm(m.x, m.y, p2_), m.z, p1_);
}

namespace {

// d(|x|/a)/dt from d(x/a)/dt: on each piece the search cuts at the coordinate planes, |x| is linear.
double rate(double coordinate, double per_radius) {
    return coordinate < 0 || (coordinate == 0 && per_radius < 0) ? -per_radius : per_radius;
}

}  // namespace

ValueAndDerivative Superellipsoid::gauge_along(const Vec3d& p, const RadiusRates& direction) const {
    const Vec3d& rates = direction.per_radius;
    const auto [u, v, w] = magnitudes(p);
    const PNorm h = p_norm_parts(u, v, p2_), g = p_norm_parts(h.norm, w, p1_);
    const auto [dh_du, dh_dv] = p_norm_partials(h, u, p2_.p);
    const auto [dg_dh, dg_dw] = p_norm_partials(g, h.norm, p1_.p);
    const double dh = dh_du * rate(p.x, rates.x) + dh_dv * rate(p.y, rates.y);
    const double slope = dg_dh * dh + dg_dw * rate(p.z, rates.z);
    return {g.norm, std::isfinite(slope) ? slope : NAN};
}

// Within the box the squares are a few units, rounded to 10⁻¹⁵; the gauge is within 2⁻⁴⁶ of itself.
constexpr double kQuadricMargin = 1e-8;

std::optional<Interval> Superellipsoid::enclosing_stretch(const Vec3d& start, const Vec3d& direction, double length,
                                                         QuadricForm form) const {
    constexpr double kBound = 1 + kQuadricMargin;
    const QuadricScales& k = scales(form);
    const std::optional<Interval> cylinder = within_quadric(k.cylinder, start, direction, length, kBound);
    if (!cylinder) return std::nullopt;
    const std::optional<Interval> ellipsoid = within_quadric(k.ellipsoid, start, direction, length, kBound);
    if (!ellipsoid) return std::nullopt;
    const Interval both{std::max(cylinder->lo, ellipsoid->lo), std::min(cylinder->hi, ellipsoid->hi)};
    return both.lo <= both.hi ? std::optional<Interval>(both) : std::nullopt;
}

std::optional<Interval> Superellipsoid::inscribed_stretch(const Vec3d& start, const Vec3d& direction, double length,
                                                         QuadricForm form) const {
    return within_quadric(scales(form).inscribed, start, direction, length, 1 - kQuadricMargin);
}

double Superellipsoid::nearest_to_centre(const Vec3d& start, const Vec3d& direction, double length,
                                         QuadricForm form) const {
    return nearest_in_quadric(scales(form).inscribed, start, direction, length);
}

// h = ‖(u, v)‖_p2 is convex along a piece for p2 ≥ 1 and concave for p2 ≤ 1; R(w) = (1 − w^p1)^(1/p1), the edge of
// the p1-ball, is concave for p1 ≥ 1 and convex for p1 ≤ 1. With one exponent on each side of 2 both are convex or
// both concave, and φ = h − R is their difference (negated for the concave pair).
Superellipsoid::GaugeAndDifference Superellipsoid::gauge_and_difference(const Vec3d& p,
                                                                        const RadiusRates& direction) const {
    const Vec3d& rates = direction.per_radius;
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double p1 = p1_.p, p2 = p2_.p;
    const auto [u, v, z] = magnitudes(p);
    const double w = std::min(z, 1.0);
    const PNorm h = p_norm_parts(u, v, p2_);
    const double gauge = p_norm(h.norm, z, p1_);  // as gauge(p) takes it
    const auto [dh_du, dh_dv] = p_norm_partials(h, u, p2);
    const double h_slope = dh_du * rate(p.x, rates.x) + dh_dv * rate(p.y, rates.y);
    const double w_power = p1_.unit_power(w), rest = 1 - w_power;
    const double edge = rest > 0 ? p1_.any_root(rest) : 0;
    // dR/dw = −w^(p1−1)·R^(1−p1) = −(w^p1/w)·(R/(1 − w^p1)), with its limits at w = 0 and w = 1.
    const double dr_dw = w == 0      ? (p1 > 1 ? 0 : p1 == 1 ? -1 : -inf)
                         : rest <= 0 ? (p1 < 1 ? 0 : -inf)
                                     : -(w_power / w) * (edge / rest);
    const double edge_slope = dr_dw * rate(p.z, rates.z);
    const ConvexSample horizontal{h.norm, std::isfinite(h_slope) ? h_slope : NAN}, vertical{edge, edge_slope};
    if (p2 >= 1) return {gauge, {horizontal, vertical}};
    return {gauge, {{-vertical.value, -vertical.slope}, {-horizontal.value, -horizontal.slope}}};
}

// The computed gauge is within a few ulps of the exact one: each operation rounds once, the powers and roots are
// within a few ulps or a few roundings, and a p-norm passes its arguments' relative errors on without amplifying them
// (an error of r^p in the sum 1 + r^p is divided by p in the root). Widened by far more than that, the corners' values
// bound the exact gauge over the box, and the computed one too (which need not be monotone in its last bits).
constexpr double kGaugeRelativeError = 0x1p-46;

Interval Superellipsoid::gauge_range(const IntervalBox& box) const { return {least_gauge(box), most_gauge(box)}; }

double Superellipsoid::least_gauge(const IntervalBox& box) const {
    return gauge(box.magnitude().lower()) * (1 - kGaugeRelativeError);
}

double Superellipsoid::most_gauge(const IntervalBox& box) const {
    return gauge(box.magnitude().upper()) * (1 + kGaugeRelativeError);
}

namespace {

// The powers p − 1 of a's and b's shares of ‖(a, b)‖_p.
struct SharePowers {
    double first, second;
};

// The ranges of (a/‖(a, b)‖_p)^(p−1) and of the same power of b's share for a, b ≥ 0 in the given ranges: both are
// monotone in t = (b/a)^p, as (1 + t)^(1/p − 1) and (1 + 1/t)^(1/p − 1), so their values at t's two extreme pairs
// bound them once widened outward by more than their rounding: r^p of a fractional p is within six ulps, of a
// whole one within p − 1 roundings. Where a = b = 0 is possible a share is undefined and every value in [0, 1] is
// allowed, which t ∈ [0, ∞] gives: the ends take the limits.
struct ShareRanges {
    Interval first, second;
};

ShareRanges share_powers(Interval a, Interval b, const NormExponent& p) {
    if (p.p == 1) return {{1, 1}, {1, 1}};
    constexpr double inf = std::numeric_limits<double>::infinity(), kRelativeError = 0x1p-36;
    const double vanishing = p.p > 1 ? 0 : inf;  // a power p − 1 of a share that is 0
    // At one pair, not both 0, from its p-norm's parts.
    const auto at = [&](double a_end, double b_end) {
        const auto [of_larger, of_smaller] = share_powers_at(p_norm_parts(a_end, b_end, p), vanishing);
        return a_end >= b_end ? SharePowers{of_larger, of_smaller} : SharePowers{of_smaller, of_larger};
    };
    const SharePowers at_lo = b.lo == 0 ? SharePowers{1, vanishing} : at(a.hi, b.lo);  // t least
    const SharePowers at_hi = a.lo == 0 ? SharePowers{vanishing, 1} : at(a.lo, b.hi);  // t most
    const auto widened = [](double lo, double hi) { return Interval{lo * (1 - kRelativeError), hi * (1 + kRelativeError)}; };
    // p > 1: the first falls and the second rises with t; p < 1 the other way round.
    if (p.p > 1) return {widened(at_hi.first, at_lo.first), widened(at_lo.second, at_hi.second)};
    return {widened(at_lo.first, at_hi.first), widened(at_hi.second, at_lo.second)};
}

// The product of two ranges of non-negative values, where 0·∞ bounds stay 0 below and ∞ above.
Interval non_negative_product(Interval a, Interval b) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {a.lo == 0 || b.lo == 0 ? 0 : a.lo * b.lo, a.hi == inf || b.hi == inf ? inf : a.hi * b.hi};
}

// ∂|x|/∂x times a non-negative factor over x's range: the factor's range, negated or made symmetric by sign.
Interval signed_by(Interval x, Interval factor) {
    if (x.lo >= 0) return factor;
    if (x.hi <= 0) return {-factor.hi, -factor.lo};
    return {-factor.hi, factor.hi};
}

}  // namespace

// ∂G/∂u = (h/G)^(p1−1)·(u/h)^(p2−1), ∂G/∂v likewise, ∂G/∂w = (w/G)^(p1−1), with h = ‖(u, v)‖_p2, p = 2/ε and
// u = |x|/a1, ...; every factor is a power of a share in [0, 1], bounded from the ranges of u, v, w, h.
IntervalBox Superellipsoid::gradient_range(const IntervalBox& box) const {
    const Interval u = box.x.magnitude() * inverse_radii_.x, v = box.y.magnitude() * inverse_radii_.y,
                   w = box.z.magnitude() * inverse_radii_.z;
    const Interval h = {p_norm(u.lo, v.lo, p2_), p_norm(u.hi, v.hi, p2_)};
    const auto [horizontal, d_dw] = share_powers(h, w, p1_);
    const auto [of_u, of_v] = share_powers(u, v, p2_);
    const Interval d_du = non_negative_product(horizontal, of_u), d_dv = non_negative_product(horizontal, of_v);
    return {signed_by(box.x, d_du * inverse_radii_.x), signed_by(box.y, d_dv * inverse_radii_.y),
            signed_by(box.z, d_dw * inverse_radii_.z)};
}


Vec3d Superellipsoid::normal(const Vec3d& p) const {
    const auto [u, v, w] = magnitudes(p);
    // ∂G/∂u = ∂G/∂h·∂h/∂u and so on, from the p-norms' parts as the gauge takes them: without logarithms where the
    // partials are finite (off the coordinate planes of exponents above 2), and scaled by the largest before the
    // normalisation, so that neither their squares overflow nor their sizes matter.
    const PNorm h = p_norm_parts(u, v, p2_), g = p_norm_parts(h.norm, w, p1_);
    const auto [dh_du, dh_dv] = p_norm_partials(h, u, p2_.p);
    const auto [dg_dh, dg_dw] = p_norm_partials(g, h.norm, p1_.p);
    const Vec3d gradient(dg_dh * dh_du * inverse_radii_.x, dg_dh * dh_dv * inverse_radii_.y, dg_dw * inverse_radii_.z);
    const double largest = max_component(gradient);
    if (is_finite(gradient) && largest > 0) {
        const double scale = 1 / largest;
        return normalize(Vec3d(std::copysign(gradient.x * scale, p.x), std::copysign(gradient.y * scale, p.y),
                               std::copysign(gradient.z * scale, p.z)));
    }
    return limit_normal(p);
}

Vec3d Superellipsoid::limit_normal(const Vec3d& p) const {
    const double p1 = p1_.p, p2 = p2_.p;
    const Vec3d scaled = magnitudes(p);
    const double size = max_component(scaled);
    if (size == 0) return {0, 0, 1};
    // ∂G/∂u = (h/G)^(p1−1)·(u/h)^(p2−1), ∂G/∂w = (w/G)^(p1−1), h = ‖(u, v)‖_p2. Magnitudes are floored at a tiny
    // fraction of the point's size, which turns the limits at the coordinate planes (0, 1 or ∞ per component)
    // into finite logarithms; the components are then compared in log space so none overflows.
    const double floor = size * 1e-200;
    const double u = std::max(scaled.x, floor), v = std::max(scaled.y, floor), w = std::max(scaled.z, floor);
    const double h = p_norm(u, v, p2_), g = p_norm(h, w, p1_);
    const double horizontal = (p1 - 1) * std::log(h / g);
    const double log_x = horizontal + (p2 - 1) * std::log(u / h) - log_radii_.x;
    const double log_y = horizontal + (p2 - 1) * std::log(v / h) - log_radii_.y;
    const double log_z = (p1 - 1) * std::log(w / g) - log_radii_.z;
    const double largest = std::max({log_x, log_y, log_z});
    // exp(0) is exactly 1: the largest component needs no call.
    const auto component = [&](double c, double log_c) {
        return (c < 0 ? -1.0 : 1.0) * (log_c == largest ? 1.0 : std::exp(log_c - largest));
    };
    return normalize(Vec3d(component(p.x, log_x), component(p.y, log_y), component(p.z, log_z)));
}

std::vector<IntervalBox> Superellipsoid::surface_cells(int per_axis) const {
    std::vector<IntervalBox> cells;
    const auto edge = [&](int k, int i) { return radii_[k] * (2.0 * i / per_axis - 1); };
    for (int i = 0; i < per_axis; ++i)
        for (int j = 0; j < per_axis; ++j)
            for (int l = 0; l < per_axis; ++l) {
                const IntervalBox cell{{edge(0, i), edge(0, i + 1)}, {edge(1, j), edge(1, j + 1)}, {edge(2, l), edge(2, l + 1)}};
                if (gauge_range(cell).contains(1)) cells.push_back(cell);
            }
    return cells;
}

Vec3d Superellipsoid::surface_point(double eta, double omega) const {
    const double ce = signed_power(std::cos(eta), north_south_);
    return {radii_.x * ce * signed_power(std::cos(omega), east_west_),
            radii_.y * ce * signed_power(std::sin(omega), east_west_),
            radii_.z * signed_power(std::sin(eta), north_south_)};
}

}  // namespace isotrace
