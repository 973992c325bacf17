// The implicit field of a box: the signed distance to the box in its own frame, carried to the object by the
// box's placement (exact distance for rigid placements, a field with the same zero set for any affine one).
#include <cmath>

#include "geometry/box/box_shape.h"
#include "geometry/field/transformed_field.h"

namespace isotrace {
namespace {

// The box half_size around the origin.
class CentredBoxField final : public ImplicitField {
public:
    explicit CentredBoxField(const Vec3d& half_size) : half_size_(half_size) {}

    double value(const Vec3d& p) const override {
        const Vec3d q = abs(p) - half_size_;
        return length(max(q, Vec3d{})) + std::min(max_component(q), 0.0);
    }
    Vec3d gradient(const Vec3d& p) const override {
        const Vec3d q = abs(p) - half_size_;
        Vec3d g;
        if (max_component(q) > 0) {
            g = max(q, Vec3d{});
            g = g / length(g);
        } else {  // inside: the nearest face's normal
            const int axis = q.x >= q.y && q.x >= q.z ? 0 : (q.y >= q.z ? 1 : 2);
            g[axis] = 1;
        }
        for (int k = 0; k < 3; ++k)
            if (p[k] < 0) g[k] = -g[k];
        return g;
    }
    FieldBox bounds() const override { return {-half_size_, half_size_}; }
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        return std::abs(value(centre)) <= radius;
    }
    // With q = |p| − h per axis: the length of q's positive part plus its largest component where that is negative.
    Interval value_range(const IntervalBox& box) const override {
        double outside_lo = 0, outside_hi = 0;
        Interval largest{-INFINITY, -INFINITY};
        for (int k = 0; k < 3; ++k) {
            const Interval q = box[k].magnitude() + (-half_size_[k]);
            outside_lo += std::max(q.lo, 0.0) * std::max(q.lo, 0.0);
            outside_hi += std::max(q.hi, 0.0) * std::max(q.hi, 0.0);
            largest = max(largest, q);
        }
        return Interval{std::sqrt(outside_lo), std::sqrt(outside_hi)} + Interval{std::min(largest.lo, 0.0), std::min(largest.hi, 0.0)};
    }
    // A distance: 1-Lipschitz.
    Interval slope_range(const IntervalBox& box, const Vec3d& direction) const override {
        (void)box;
        return {-length(direction), length(direction)};
    }

private:
    Vec3d half_size_;
};

}  // namespace

std::unique_ptr<ImplicitField> BoxShape::implicit_field() const {
    return transformed_field(std::make_unique<CentredBoxField>(half_size()), to_object());
}

}  // namespace isotrace
