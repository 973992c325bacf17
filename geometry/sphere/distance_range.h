#pragma once
// The interval of |p − centre| over the points p of a box (its nearest and farthest points, axis by axis): the
// spheres' field bounds, and a ball container's.
#include <cmath>

#include "renderer/math/interval.h"

namespace isotrace {

inline Interval distance_range(const IntervalBox& box, const Vec3d& centre) {
    double near2 = 0, far2 = 0;
    for (int k = 0; k < 3; ++k) {
        const Interval offset = box[k] + (-centre[k]);
        const Interval m = offset.magnitude();
        near2 += m.lo * m.lo;
        far2 += m.hi * m.hi;
    }
    return {std::sqrt(near2), std::sqrt(far2)};
}

}  // namespace isotrace
