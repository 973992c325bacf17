#include "geometry/superquadric/superquadric_along_ray.h"

#include <limits>

namespace isotrace {

SuperquadricAlongRay::SuperquadricAlongRay(const Superquadric& superquadric, const Vec3d& origin,
                                           const Vec3d& direction, std::uint64_t* point_values)
    : superquadric_(superquadric),
      origin_(superquadric.placement().inverse_point(origin)),
      direction_(superquadric.placement().inverse_vector(direction)),
      rates_(superquadric.shape().rates_along(direction_)),
      point_values_(point_values) {}

ValueAndDerivative SuperquadricAlongRay::value_and_slope(double t) const {
    count_value();
    const Vec3d point = point_at(t);
    if (superquadric_.deformation().empty()) {
        const ValueAndDerivative gauge = superquadric_.shape().gauge_along(point, rates_);
        return {gauge.value - 1, gauge.derivative};
    }
    Vec3d velocity = direction_;
    const std::optional<Vec3d> undeformed = superquadric_.deformation().inverse_along(point, velocity);
    if (!undeformed) return {1, std::numeric_limits<double>::quiet_NaN()};  // outside a stage box: outside
    const ValueAndDerivative gauge = superquadric_.shape().gauge_along(*undeformed, velocity);
    return {gauge.value - 1, gauge.derivative};
}

Vec3d SuperquadricAlongRay::point_at(double t) const {
    const Vec3d point = origin_ + direction_ * t;
    if (superquadric_.deformation().empty()) return point;
    return superquadric_.deformation().deformed_box().nearest(point);
}

IntervalBox SuperquadricAlongRay::stretch(double a, double b) const {
    IntervalBox box = IntervalBox::point(point_at(a));
    box.extend(point_at(b));
    return box;
}

const DeformationChain::InverseBoxes* SuperquadricAlongRay::walked(double a, double b) const {
    if (!walked_ || a != walked_a_ || b != walked_b_) {
        if (!walked_) walked_.emplace();
        walked_a_ = a, walked_b_ = b;
        walked_inside_ = superquadric_.deformation().inverse_boxes(stretch(a, b), *walked_, kBeyond);
        walked_bound_.reset();
    }
    return walked_inside_ ? &*walked_ : nullptr;
}

Interval SuperquadricAlongRay::bound(double a, double b) const {
    const DeformationChain::InverseBoxes* boxes = walked(a, b);
    if (!walked_bound_) walked_bound_ = boxes ? superquadric_.field_range(*boxes) : Interval{1, 1};
    return *walked_bound_;
}

Interval SuperquadricAlongRay::slope_bound(double a, double b) const {
    const DeformationChain::InverseBoxes* boxes = walked(a, b);
    if (!boxes || boxes->clipped) return Interval::unbounded();
    return superquadric_.deformation().gauge_slope(*boxes, IntervalBox::point(direction_));
}

}  // namespace isotrace
