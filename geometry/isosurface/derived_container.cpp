#include "geometry/isosurface/derived_container.h"

#include <cmath>
#include <limits>

namespace isotrace {
namespace {

// Whether f > 0 is proven over every point whose |coordinate| on some axis is at least `half_size`.
bool positive_outside_cube(const ImplicitField& field, double half_size) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis)
        for (const Interval side : {Interval{half_size, inf}, Interval{-inf, -half_size}}) {
            IntervalBox slab = IntervalBox{Interval::unbounded(), Interval::unbounded(), Interval::unbounded()};
            slab[axis] = side;
            if (!(field.value_range(slab).lo > 0)) return false;  // NaN proves nothing
        }
    return true;
}

}  // namespace

std::optional<Container> derive_container(const ImplicitField& field) {
    for (int k = kSmallestDerivedHalfSize; k <= kLargestDerivedHalfSize; ++k) {
        const double half_size = std::ldexp(1.0, k);
        if (positive_outside_cube(field, half_size))
            return Container::box({-half_size, -half_size, -half_size}, {half_size, half_size, half_size});
    }
    return std::nullopt;
}

}  // namespace isotrace
