#pragma once
// The container of an isosurface (POV-Ray's contained_by): a box or a ball that bounds the solid {f < 0}. The
// isosurface's solid is {f < 0} ∩ container, so where the function is negative on the container's boundary the
// boundary itself is surface, and the solid is closed (a CSG operand, a closed mesh when polygonised).
#include <optional>

#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"

namespace isotrace {

class Container {
public:
    static Container box(const Vec3d& lower, const Vec3d& upper);
    static Container sphere(const Vec3d& centre, double radius);

    // The axis-aligned box around the container.
    const IntervalBox& bounds() const { return bounds_; }
    // The closed part of [t_min, t_max] where origin + t·direction lies in the container, or nothing.
    std::optional<Interval> clip(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max) const;
    // Negative inside, zero on the boundary; the Euclidean distance outside.
    double signed_distance(const Vec3d& p) const;
    // The outward normal of the boundary nearest to p.
    Vec3d normal(const Vec3d& p) const;
    // An interval containing signed_distance over `cell`.
    Interval distance_range(const IntervalBox& cell) const;
    // Whether `cell` may hold a point of the boundary (conservative).
    bool boundary_may_meet(const IntervalBox& cell) const;

private:
    bool is_sphere_ = false;
    Vec3d centre_;
    double radius_ = 0;
    IntervalBox bounds_;
};

}  // namespace isotrace
