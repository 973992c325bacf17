// The implicit field of an isosurface for the polygonisers, textures and other isosurfaces: max(f, d), d the
// container's signed distance, whose zero set is the boundary of {f < 0} ∩ container. Its interval bounds follow
// from f's and d's (d is 1-Lipschitz), so an isosurface used as a term of another keeps that search guaranteed.
#include <algorithm>

#include "geometry/isosurface/isosurface_shape.h"

namespace isotrace {
namespace {

class IsosurfaceField final : public ImplicitField {
public:
    explicit IsosurfaceField(const IsosurfaceShape& shape) : shape_(shape) {}

    double value(const Vec3d& p) const override { return -*shape_.field_value(p); }
    Vec3d gradient(const Vec3d& p) const override { return -shape_.field_gradient(p); }
    FieldBox bounds() const override {
        const IntervalBox& b = shape_.container().bounds();
        return {b.lower(), b.upper()};
    }
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        const Vec3d r{radius, radius, radius};
        IntervalBox ball = IntervalBox::point(centre - r);
        ball.extend(centre + r);
        return !value_range(ball).excludes_zero();
    }
    Interval value_range(const IntervalBox& box) const override {
        const Interval f = shape_.field().value_range(box), d = shape_.container().distance_range(box);
        return max(f, d);
    }
    // The derivative of a max is one of its operands' where it exists.
    Interval slope_range(const IntervalBox& box, const Vec3d& direction) const override {
        const Interval f = shape_.field().value_range(box), d = shape_.container().distance_range(box);
        const double reach = length(direction);
        const Interval d_slope{-reach, reach};
        if (d.hi < f.lo) return shape_.field().slope_range(box, direction);
        if (f.hi < d.lo) return d_slope;
        return hull(shape_.field().slope_range(box, direction), d_slope);
    }

private:
    const IsosurfaceShape& shape_;
};

}  // namespace

std::unique_ptr<ImplicitField> IsosurfaceShape::implicit_field() const { return std::make_unique<IsosurfaceField>(*this); }

}  // namespace isotrace
