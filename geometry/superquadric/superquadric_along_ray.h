#pragma once
// One superquadric along one ray, in its local deformed frame (where the placement keeps t): the inside function
// g(t) = G(D⁻¹(o + t·d)) − 1 and what the crossing search (crossing_search.h) needs to know of it over a stretch
// [a, b] of the ray — an interval bound of g, from the deformation chain's interval inverse and the gauge's
// monotonicity in |x|, |y|, |z|, and an interval bound of g′, from the gauge's gradient range and the chain's
// interval inverse Jacobians (a bound of g′ that excludes zero proves g strictly monotone on [a, b]). g is continued
// beyond the undeformed box by the gauge (DeformationChain::BeyondUndeformedBox::Gauge), not cut to 1 there: a
// stretch that reaches past a face of that box, as those near a boxy shape's surface do, keeps its bound of g′.
// Nor is it cut at the faces of the deformed box, which the search's stretches lie within: a point that the rounding
// of a stretch's end puts just beyond a face is taken at the face (g is positive there, the solid lying strictly
// inside), so that the bounds of g′ over the cells and stretches at the faces hold for every point the search asks.
#include <cstdint>
#include <limits>
#include <optional>

#include "renderer/math/interval.h"
#include "geometry/superquadric/superquadric.h"

namespace isotrace {

// One per query: it keeps the walk of the last stretch it bounded (not to be shared between threads).
class SuperquadricAlongRay {
public:
    // `origin` and `direction` in the superquadric's shape space; every point value taken is counted in
    // `point_values` when given.
    SuperquadricAlongRay(const Superquadric& superquadric, const Vec3d& origin, const Vec3d& direction,
                         std::uint64_t* point_values = nullptr);

    const Vec3d& local_origin() const { return origin_; }
    const Vec3d& local_direction() const { return direction_; }

    double value(double t) const {
        count_value();
        return superquadric_.local_field(point_at(t), kBeyond);
    }
    // g(t) (bit for bit value(t)) and g′(t) (NaN where unknown: outside a stage box, on a crease).
    ValueAndDerivative value_and_slope(double t) const;
    // An undeformed superquadric's gauge at t and its parts as a difference of convex functions
    // (Superellipsoid::gauge_and_difference).
    Superellipsoid::GaugeAndDifference gauge_and_difference(double t) const {
        count_value();
        return superquadric_.shape().gauge_and_difference(point_at(t), rates_);
    }
    // Contains g over [a, b] (points outside an inner stage box of a deformation count as outside, g = 1).
    Interval bound(double a, double b) const;
    // Contains g′ over [a, b] wherever g is differentiable; unbounded when some of the stretch lies outside an inner
    // stage box (g is not continuous there) or the gradient is unbounded.
    Interval slope_bound(double a, double b) const;

private:
    static constexpr DeformationChain::BeyondUndeformedBox kBeyond = DeformationChain::BeyondUndeformedBox::Gauge;

    void count_value() const {
        if (point_values_) ++*point_values_;
    }
    // The ray's point at t, taken into the deformed box (of a deformed shape; the box's faces, which the field is
    // not cut at, lie rounding errors away from where the search asks).
    Vec3d point_at(double t) const;
    IntervalBox stretch(double a, double b) const;
    // The inverse walk of stretch(a, b) (nullptr when no part of it lies inside every stage box), kept for the last
    // stretch asked about: the search asks for the bound of g and then of g′ over the same stretch, and the walk
    // (atan2s and sines through a bend) is most of either.
    const DeformationChain::InverseBoxes* walked(double a, double b) const;

    const Superquadric& superquadric_;
    Vec3d origin_, direction_;
    Superellipsoid::RadiusRates rates_;  // taken once: the ray's direction is the same all along it undeformed
    std::uint64_t* point_values_;
    mutable double walked_a_ = std::numeric_limits<double>::quiet_NaN(), walked_b_ = walked_a_;
    mutable bool walked_inside_ = false;
    mutable std::optional<DeformationChain::InverseBoxes> walked_;  // made when first asked: most rays ask none
    // The bound of g over the walked stretch, once asked: a run is bounded before its search, which asks again.
    mutable std::optional<Interval> walked_bound_;
};

}  // namespace isotrace
