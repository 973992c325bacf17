#pragma once
// Helpers shared by the implicit-surface tests: random elements and rays, occlusion over every cell, and the
// error-naming check.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>

#include "geometry/implicit/blob_cell_queries.h"
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

// Occlusion as Embree asks it: each surface cell on its own, in any order, until one is occluded.
inline bool occluded_in_any_cell(const BlobGroup& group, const Vec3d& origin, const Vec3d& direction, double t_min,
                                 double t_max, BlobQueryWork& work) {
    for (std::uint32_t cell = 0; cell < group.cells().surface_cell_count(); ++cell)
        if (group.queries().occluded_in_cell(group, cell, origin, direction, t_min, t_max, work)) return true;
    return false;
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
    const double radius = 0.1 + 1.9 * u(rng);
    const double weight = u(rng) < 0.2 ? -1.0 : 1.0;
    return Metacube(box, radius, weight);
}

// `count` elements in a 3 m cube, a third of them metacubes (non-uniform half-sizes up to 0.3), radii 0.35–0.7,
// weights 0.7–1.3; every `carving_every`-th element (when > 0) carves with weight −0.5. Threshold 0.5.
inline BlobGroup random_blob_group(int count, std::uint32_t seed, const std::string& kernel, int carving_every = 0) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> position(-1.5, 1.5), radius(0.35, 0.7), half(0.0, 0.25), weight(0.7, 1.3);
    std::vector<Metacube> elements;
    for (int i = 0; i < count; ++i) {
        OrientedBox box;
        box.centre = {position(random), position(random), position(random)};
        const double d = i % 3 == 0 ? half(random) : 0.0;
        box.half_size = {d, d * 0.7, d * 1.2};
        const double r = radius(random), w = weight(random);
        elements.emplace_back(box, r, carving_every > 0 && i % carving_every == 0 ? -0.5 : w);
    }
    return BlobGroup(std::move(elements), make_field_function(kernel, 4.0), 0.5);
}

}  // namespace isotrace
