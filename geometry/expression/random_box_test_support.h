#pragma once
// Random boxes and points for the noise bounds' sampling tests.
#include <random>

#include "renderer/math/interval.h"

namespace isotrace {

// A box with its lower corner in [−reach, reach)³ and each side up to `size` wide.
inline IntervalBox random_box(std::mt19937_64& random, double reach, double size) {
    std::uniform_real_distribution<double> unit(0, 1);
    IntervalBox box;
    for (int k = 0; k < 3; ++k) {
        const double lo = -reach + 2 * reach * unit(random);
        box[k] = {lo, lo + size * unit(random)};
    }
    return box;
}

inline Vec3d random_point(std::mt19937_64& random, const IntervalBox& box) {
    std::uniform_real_distribution<double> unit(0, 1);
    return {box.x.lo + box.x.width() * unit(random), box.y.lo + box.y.width() * unit(random),
            box.z.lo + box.z.width() * unit(random)};
}

}  // namespace isotrace
