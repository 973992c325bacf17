#pragma once
// Helpers shared by the implicit-surface tests: random elements and rays, and the error-naming check.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>

#include "geometry/implicit/metacube.h"

namespace isotrace {

// Expects std::invalid_argument whose message starts with "<field>:".
inline void expect_invalid_naming(const std::function<void()>& call, const std::string& field) {
    try {
        call();
        ADD_FAILURE() << "no exception; expected one naming " << field;
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()).rfind(field + ":", 0), 0u) << error.what();
    }
}

// A uniformly random rotation (normalised quaternion of four Gaussians) as orthonormal axes.
inline std::array<Vec3d, 3> random_axes(std::mt19937_64& rng) {
    std::normal_distribution<double> gauss;
    double w = gauss(rng), x = gauss(rng), y = gauss(rng), z = gauss(rng);
    const double n = std::sqrt(w * w + x * x + y * y + z * z);
    w /= n, x /= n, y /= n, z /= n;
    return {Vec3d{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
            Vec3d{2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
            Vec3d{2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}};
}

inline Vec3d random_vector(std::mt19937_64& rng, double low, double high) {
    std::uniform_real_distribution<double> u(low, high);
    return {u(rng), u(rng), u(rng)};
}

// A rotated, non-uniform metacube; some half-sizes are 0 (flat or line skeletons, metaballs) now and then.
inline Metacube random_metacube(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    OrientedBox box;
    box.centre = random_vector(rng, -2, 2);
    box.axes = random_axes(rng);
    for (int k = 0; k < 3; ++k) box.half_size[k] = u(rng) < 0.15 ? 0 : 1.5 * u(rng);
    return Metacube(box, 0.1 + 1.9 * u(rng), u(rng) < 0.2 ? -1.0 : 1.0);
}

}  // namespace isotrace
