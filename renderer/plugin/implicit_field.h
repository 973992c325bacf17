#pragma once
// ImplicitField: what every polygoniser asks of a surface, and nothing about the shape behind it. A field f is
// negative inside, positive outside and zero on the surface; its gradient points outwards. Value and gradient at
// a lattice crossing are the Hermite data of dual contouring. f need not be a distance: only its sign, its zero
// set and the direction of its gradient carry meaning, and |f|/|∇f| estimates the distance near the surface.
//
// Shapes offer their field through Shape::implicit_field(); each primitive's field lives in the primitive's own
// folder.
#include <cstddef>
#include <limits>
#include <memory>
#include <span>

#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"

namespace isotrace {

// An axis-aligned box, lower ≤ upper.
struct FieldBox {
    Vec3d lower, upper;

    // The box that extend() grows from (lower > upper).
    static FieldBox none() {
        constexpr double inf = std::numeric_limits<double>::infinity();
        return {{inf, inf, inf}, {-inf, -inf, -inf}};
    }
    void extend(const Vec3d& p) {
        lower = min(lower, p);
        upper = max(upper, p);
    }
    void extend(const FieldBox& box) {
        lower = min(lower, box.lower);
        upper = max(upper, box.upper);
    }

    Vec3d centre() const { return (lower + upper) * 0.5; }
    Vec3d extent() const { return upper - lower; }
    bool contains(const Vec3d& p) const {
        return lower.x <= p.x && p.x <= upper.x && lower.y <= p.y && p.y <= upper.y && lower.z <= p.z &&
               p.z <= upper.z;
    }
    // Distance from p to the box (0 inside).
    double distance(const Vec3d& p) const { return length(max(max(lower - p, p - upper), Vec3d{})); }
};

// The value of a field at a point and its derivative along a direction (a Newton step's two numbers).
struct FieldSlope {
    double value, derivative;
};

// Intervals of a field's value and of its derivative along a direction over a box.
struct FieldRanges {
    Interval value, slope;
};

class ImplicitField {
public:
    virtual ~ImplicitField() = default;

    virtual double value(const Vec3d& p) const = 0;
    virtual Vec3d gradient(const Vec3d& p) const = 0;
    // value(p), bit for bit, and ∇f(p) · direction; a field may compute both for less than a gradient.
    virtual FieldSlope value_and_slope(const Vec3d& p, const Vec3d& direction) const {
        return {value(p), dot(gradient(p), direction)};
    }
    // value() at each of `points` (out has as many slots), bit for bit: the polygonisers sample lattice corners a
    // block at a time, and a field that can share work between nearby points (a blob group gathers the elements
    // that reach them once) overrides this.
    virtual void values(std::span<const Vec3d> points, std::span<double> out) const {
        for (std::size_t i = 0; i < points.size(); ++i) out[i] = value(points[i]);
    }
    // A box that contains the whole surface (and, for a bounded solid, the whole inside).
    virtual FieldBox bounds() const = 0;
    // Conservative: false only when no surface point lies within `radius` of `centre`. The polygonisers subdivide
    // only cells for which it is true, so a field that cannot tell may always answer true (at the cost of time).
    virtual bool may_reach_surface(const Vec3d& centre, double radius) const = 0;

    // Guaranteed bounds, for searches that must not miss a thin feature (isosurfaces that use this field as a
    // term, interval octrees): an interval that contains f over `box`, and one that contains the derivative of f
    // along `direction` over `box` wherever f is differentiable there. A field that cannot bound answers
    // Interval::unbounded(), which is always correct and only costs search time.
    virtual Interval value_range(const IntervalBox& box) const {
        (void)box;
        return Interval::unbounded();
    }
    virtual Interval slope_range(const IntervalBox& box, const Vec3d& direction) const {
        (void)box;
        (void)direction;
        return Interval::unbounded();
    }
    // Both, for a field that computes the value's interval on the way to the slope's (an expression does).
    virtual FieldRanges value_and_slope_range(const IntervalBox& box, const Vec3d& direction) const {
        return {value_range(box), slope_range(box, direction)};
    }
    // The slope_range along each axis (the partial derivatives' intervals), for a field that computes the three
    // for less than three slopes (an expression does).
    virtual IntervalBox gradient_range(const IntervalBox& box) const {
        return {slope_range(box, {1, 0, 0}), slope_range(box, {0, 1, 0}), slope_range(box, {0, 0, 1})};
    }
};

}  // namespace isotrace
