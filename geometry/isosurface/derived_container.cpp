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

// Moves each face of `box` (outside which f > 0 is proven) inwards as far as f > 0 is proven over the slab of
// the box between the face and its new place, by bisection: a solid off the origin gets a box about it, not the
// cube about the origin. A face is never moved onto the opposite one.
void tighten_faces(const ImplicitField& field, IntervalBox& box) {
    constexpr int kBisections = 48;
    for (int axis = 0; axis < 3; ++axis)
        for (const bool upper : {true, false}) {
            double proven = upper ? box[axis].hi : box[axis].lo;           // f > 0 beyond it
            double unproven = upper ? box[axis].lo : box[axis].hi;
            for (int step = 0; step < kBisections; ++step) {
                const double mid = 0.5 * (proven + unproven);
                IntervalBox slab = box;
                slab[axis] = upper ? Interval{mid, box[axis].hi} : Interval{box[axis].lo, mid};
                if (field.value_range(slab).lo > 0) proven = mid;
                else unproven = mid;
            }
            (upper ? box[axis].hi : box[axis].lo) = proven;
        }
}

}  // namespace

std::optional<Container> derive_container(const ImplicitField& field) {
    for (int k = kSmallestDerivedHalfSize; k <= kLargestDerivedHalfSize; ++k) {
        const double half_size = std::ldexp(1.0, k);
        if (!positive_outside_cube(field, half_size)) continue;
        IntervalBox box{{-half_size, half_size}, {-half_size, half_size}, {-half_size, half_size}};
        tighten_faces(field, box);
        return Container::box(box.lower(), box.upper());
    }
    return std::nullopt;
}

}  // namespace isotrace
