#pragma once
// What the crossing search may know of a field g over one cell of a surface shell before it looks along a ray: g at
// the cell's centre and a bound of each partial derivative over the cell (slightly enlarged, so that rays padded past
// its faces stay inside). By the mean value theorem g over any segment of the cell lies within
// value + Σₖ ∂ₖg·(xₖ − centreₖ), and g′ along a direction d within Σₖ ∂ₖg·dₖ: a few products per cell a ray
// crosses, where bounding g over a stretch of the ray takes an interval walk through the deformations.
#include <algorithm>

#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct ShellCellBounds {
    Vec3d centre;
    double value = 0;
    IntervalBox gradient;  // ∂g/∂x, ∂g/∂y, ∂g/∂z over the cell
    bool known = false;    // false where g has no finite gradient bound (a crease, a cell an inner stage box clips)

    // Contains g′ along `direction` over the cell.
    Interval slope(const Vec3d& direction) const {
        return gradient.x * direction.x + gradient.y * direction.y + gradient.z * direction.z;
    }
    // Contains g over the segment from a to b (both in the cell). At each point x the gradient's bounds give
    // g ≥ value + Σₖ min(∂ₖg·(xₖ − centreₖ)) over ∂ₖg in its bounds, a sum of minima of linear functions, concave
    // along the segment: its least value lies at an end, and likewise the upper bound's greatest. So the range is
    // that of the two ends, tighter than the interval product of the gradient's bounds with the segment's box,
    // which lets each axis take its own worst end.
    Interval range(const Vec3d& a, const Vec3d& b) const {
        Interval g_a = Interval::point(value), g_b = g_a;
        for (int k = 0; k < 3; ++k) {
            g_a = g_a + gradient[k] * (a[k] - centre[k]);
            g_b = g_b + gradient[k] * (b[k] - centre[k]);
        }
        return {std::min(g_a.lo, g_b.lo) - kRounding, std::max(g_a.hi, g_b.hi) + kRounding};
    }
    // Contains g over a box that holds the centre and lies within the cell (the cell itself): each axis's term takes
    // its own worst end.
    Interval range(const IntervalBox& box) const {
        Interval g = Interval::point(value);
        for (int k = 0; k < 3; ++k) g = g + gradient[k] * Interval{box[k].lo - centre[k], box[k].hi - centre[k]};
        return {g.lo - kRounding, g.hi + kRounding};
    }

private:
    // The centre's value and the products are rounded: the ranges are widened by far more than their errors.
    static constexpr double kRounding = 1e-12;
};

}  // namespace isotrace
