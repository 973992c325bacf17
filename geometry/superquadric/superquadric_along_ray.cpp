#include "geometry/superquadric/superquadric_along_ray.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isotrace {

SuperquadricAlongRay::SuperquadricAlongRay(const Superquadric& superquadric, const Vec3d& origin,
                                           const Vec3d& direction)
    : superquadric_(superquadric),
      origin_(superquadric.placement().inverse_point(origin)),
      direction_(superquadric.placement().inverse_vector(direction)) {}

ValueAndDerivative SuperquadricAlongRay::value_and_slope(double t) const {
    Vec3d velocity = direction_;
    const std::optional<Vec3d> undeformed = superquadric_.deformation().inverse_along(origin_ + direction_ * t, velocity);
    if (!undeformed) return {1, std::numeric_limits<double>::quiet_NaN()};  // outside a stage box: outside
    const ValueAndDerivative gauge = superquadric_.shape().gauge_along(*undeformed, velocity);
    return {gauge.value - 1, gauge.derivative};
}

IntervalBox SuperquadricAlongRay::stretch(double a, double b) const {
    IntervalBox box = IntervalBox::point(origin_ + direction_ * a);
    box.extend(origin_ + direction_ * b);
    return box;
}

const DeformationChain::InverseBoxes* SuperquadricAlongRay::walked(double a, double b) const {
    if (!walked_ || a != walked_a_ || b != walked_b_) {
        if (!walked_) walked_.emplace();
        walked_a_ = a, walked_b_ = b;
        walked_inside_ = superquadric_.deformation().inverse_boxes(stretch(a, b), *walked_, kBeyond);
        derived_ = false;
    }
    return walked_inside_ ? &*walked_ : nullptr;
}

namespace {

// Σ xₖ·yₖ over three components.
Interval dot_range(const IntervalBox& x, const IntervalBox& y) {
    Interval sum{0, 0};
    for (int k = 0; k < 3; ++k) sum = sum + x[k] * y[k];
    return sum;
}

bool is_finite(const IntervalBox& box) { return box.x.is_finite() && box.y.is_finite() && box.z.is_finite(); }

// The intersection of a bound with a centred form's (which holds the same values, so they meet; should rounding
// beyond the margins ever part them, the first bound alone).
Interval tighter(Interval bound, Interval centred) {
    const Interval both{std::max(bound.lo, centred.lo), std::min(bound.hi, centred.hi)};
    return both.lo <= both.hi ? both : bound;
}

}  // namespace

const SuperquadricAlongRay::StretchDerivatives& SuperquadricAlongRay::derivatives(double a, double b) const {
    const DeformationChain::InverseBoxes* boxes = walked(a, b);
    if (derived_) return derivatives_;
    derived_ = true;
    derivatives_ = {};
    if (!boxes || boxes->clipped) return derivatives_;
    const IntervalBox tangent = superquadric_.deformation().inverse_tangent(*boxes, IntervalBox::point(direction_));
    const IntervalBox gradient = superquadric_.shape().gradient_range(boxes->stage[0]);
    if (is_finite(gradient)) derivatives_.slope = dot_range(gradient, tangent);
    return derivatives_;
}

// g″ = c′ᵀ·H·c′ + ∇G·c″ along the undeformed curve c(t) = D⁻¹(o + t·d). The point values at the midpoint are within
// a few hundred roundings of exact: the margins allow 2⁻³⁰ of the largest terms of g′ and 2⁻³⁶ of G.
bool SuperquadricAlongRay::centred(double a, double b) const {
    const StretchDerivatives& first = derivatives(a, b);
    if (first.centred_tried) return first.centred;
    StretchDerivatives& d = derivatives_;
    d.centred_tried = true;
    const DeformationChain& chain = superquadric_.deformation();
    if (chain.empty() || !d.slope.is_finite() || d.slope.excludes_zero()) return false;
    const DeformationChain::InverseBoxes& boxes = *walked_;
    const DeformationChain::CurveBounds curve = chain.inverse_line_derivatives(boxes, direction_);
    const Superellipsoid::DerivativeRanges gauge = superquadric_.shape().derivative_ranges(boxes.stage[0]);
    const IntervalBox& t = curve.tangent;
    d.curvature = dot_range(gauge.gradient, curve.curvature) + gauge.xx * square(t.x) + gauge.yy * square(t.y) +
                  gauge.zz * square(t.z) + (gauge.xy * t.x * t.y + gauge.xz * t.x * t.z + gauge.yz * t.y * t.z) * 2.0;
    if (!d.curvature.is_finite()) return false;
    d.mid = 0.5 * (a + b);
    const ValueAndDerivative at_mid = value_and_slope(d.mid);
    if (!std::isfinite(at_mid.derivative)) return false;
    double largest_terms = 0;
    for (int k = 0; k < 3; ++k) largest_terms += gauge.gradient[k].magnitude().hi * t[k].magnitude().hi;
    d.value = at_mid.value, d.slope_at_mid = at_mid.derivative;
    d.value_margin = 0x1p-36 * (1 + std::abs(at_mid.value)), d.slope_margin = 0x1p-30 * largest_terms;
    return d.centred = true;
}

Interval SuperquadricAlongRay::bound(double a, double b) const {
    const DeformationChain::InverseBoxes* boxes = walked(a, b);
    if (!boxes) return Interval{1, 1};
    const Interval box = superquadric_.field_range(*boxes);
    if (box.lo >= 0 || box.hi < 0 || !centred(a, b)) return box;
    const StretchDerivatives& d = derivatives_;
    const Interval offset{a - d.mid, b - d.mid};
    const double reach = std::max(d.mid - a, b - d.mid);
    const Interval centred = Interval{d.value - d.value_margin, d.value + d.value_margin} +
                             Interval{d.slope_at_mid - d.slope_margin, d.slope_at_mid + d.slope_margin} * offset +
                             d.curvature * Interval{0, 0.5 * reach * reach};
    return tighter(box, centred);
}

Interval SuperquadricAlongRay::slope_bound(double a, double b) const {
    const StretchDerivatives& d = derivatives(a, b);
    if (!centred(a, b)) return d.slope;
    const Interval centred = Interval{d.slope_at_mid - d.slope_margin, d.slope_at_mid + d.slope_margin} +
                             d.curvature * Interval{a - d.mid, b - d.mid};
    return tighter(d.slope, centred);
}

}  // namespace isotrace
