#pragma once
// A first-order Taylor model of a field over one octree cell, made once when the cells are made, that bounds f
// over any segment inside the cell with a few multiplications and no evaluation of f:
//   f(p) ∈ f(m) + ∇f(m)·(p − m) + Σᵢ (Gᵢ − ∂ᵢf(m)) (pᵢ − mᵢ),
// m the cell's centre and Gᵢ the interval of ∂ᵢf over the cell (the mean value theorem along m → p, which lies in
// the cell). The linear part is bounded exactly by its values at the segment's ends; the remainder shrinks with
// the square of the cell's size, where an interval evaluation of f over the segment's box shrinks linearly. Most
// rays that reach a cell holding the surface pass it by (shadow rays almost always do), and this settles most of
// them without a run of the tape.
#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

struct LinearCellBound {
    Vec3d centre;
    Interval value;  // f at the centre, widened by the slack for rounding (below)
    Vec3d gradient;  // ∇f at the centre
    IntervalBox gradient_range;  // Gᵢ: unbounded where the field cannot bound its slope over the cell

    // The model of `field` over `cell` (four evaluations of the field).
    static LinearCellBound of(const ImplicitField& field, const IntervalBox& cell);

    // An interval holding f on the segment from a to b, both in the cell.
    Interval over_segment(const Vec3d& a, const Vec3d& b) const {
        const Vec3d da = a - centre, db = b - centre;
        const double la = dot(gradient, da), lb = dot(gradient, db);
        const Interval r = (gradient_range[0] + -gradient.x) * Interval::spanning(da.x, db.x) +
                           (gradient_range[1] + -gradient.y) * Interval::spanning(da.y, db.y) +
                           (gradient_range[2] + -gradient.z) * Interval::spanning(da.z, db.z);
        return {value.lo + std::min(la, lb) + r.lo, value.hi + std::max(la, lb) + r.hi};
    }

    // An interval holding ∇f · direction anywhere in the cell where f is differentiable.
    Interval slope_along(const Vec3d& direction) const {
        return gradient_range[0] * direction.x + gradient_range[1] * direction.y + gradient_range[2] * direction.z;
    }
};

}  // namespace isotrace
