#pragma once
// What the crossing search may know of a field g over one cell of a surface shell before it looks along a ray: g at
// the cell's centre and a bound of each partial derivative over the cell (slightly enlarged, so that rays padded past
// its faces stay inside). By the mean value theorem g over any segment of the cell lies within
// value + Σₖ ∂ₖg·(xₖ − centreₖ), and g′ along a direction d within Σₖ ∂ₖg·dₖ: a few products per cell a ray
// crosses, where bounding g over a stretch of the ray takes an interval walk through the deformations.
#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct ShellCellBounds {
    Vec3d centre;
    double value = 0;
    IntervalBox gradient;  // ∂g/∂x, ∂g/∂y, ∂g/∂z over the cell
    bool known = false;    // false where g has no finite gradient bound (a crease, a clipped stage box)

    // Contains g′ along `direction` over the cell.
    Interval slope(const Vec3d& direction) const {
        return gradient.x * direction.x + gradient.y * direction.y + gradient.z * direction.z;
    }
    // Contains g over the segment from a to b (both in the cell).
    Interval range(const Vec3d& a, const Vec3d& b) const {
        Interval g = Interval::point(value);
        for (int k = 0; k < 3; ++k) g = g + gradient[k] * (Interval::spanning(a[k], b[k]) + -centre[k]);
        // The centre's value and the products are rounded: widen by far more than their errors.
        constexpr double kRounding = 1e-12;
        return {g.lo - kRounding, g.hi + kRounding};
    }
};

}  // namespace isotrace
