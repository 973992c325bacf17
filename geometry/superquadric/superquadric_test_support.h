#pragma once
// Test helpers for the superquadric: building one from parameters, random deformation chains, and a dense
// sampling oracle for sign changes of the field along a ray.
#include <algorithm>
#include <random>
#include <vector>

#include "geometry/superquadric/superquadric.h"

namespace isotrace::superquadric_test {

inline Superquadric make_superquadric(const Vec3d& radii, double north_south, double east_west,
                                      const std::vector<Deformation>& stages = {}, const Transform& placement = {}) {
    const Superellipsoid shape{radii, north_south, east_west};
    DeformationChain chain(shape);
    for (const Deformation& stage : stages) chain.append(stage);
    return Superquadric(shape, std::move(chain), placement);
}

// A taper, a twist and a bend of random moderate strength (all valid over the object), in the paper's order.
inline std::vector<Deformation> random_deformations(std::mt19937& random, const Vec3d& radii) {
    std::uniform_real_distribution<double> unit(-1, 1);
    const double a3 = radii.z;
    std::vector<Deformation> stages;
    const double taper_x = 0.6 * unit(random), taper_y = 0.6 * unit(random);
    stages.push_back(Taper(taper_x, taper_y, a3));
    stages.push_back(Twist(1.5 * unit(random) / a3, a3));
    // Curvature kept well inside the validity limit (k · lateral extent < 1).
    const double lateral = 1.7 * std::max(radii.x, radii.y);
    const double curvature = 0.5 * (0.2 + 0.8 * std::abs(unit(random))) / std::max(lateral, a3);
    const double angle = 3.14159 * unit(random), centre = 0.3 * a3 * unit(random);
    stages.push_back(Bend(curvature, angle, centre, {-a3, a3}));
    return stages;
}

// A superquadric of these radii with both exponents drawn from `exponent`, then a random deformation chain (the
// draws in that order, so a seed gives the same shape with every compiler).
inline Superquadric random_deformed_superquadric(std::mt19937& random, const Vec3d& radii,
                                                 std::uniform_real_distribution<double>& exponent,
                                                 const Transform& placement = {}) {
    const double north_south = exponent(random), east_west = exponent(random);
    return make_superquadric(radii, north_south, east_west, random_deformations(random, radii), placement);
}

struct RandomRay {
    Vec3d origin, direction;
};

// Rays from a shell around the object toward random points near it (some miss, some graze), and rays from inside.
inline RandomRay random_ray(std::mt19937& random, const Vec3d& radii, bool from_inside) {
    std::uniform_real_distribution<double> unit(-1, 1);
    const Vec3d target{unit(random) * radii.x * 1.2, unit(random) * radii.y * 1.2, unit(random) * radii.z * 1.2};
    Vec3d origin{unit(random), unit(random), unit(random)};
    origin = from_inside ? origin * 0.3 * std::min({radii.x, radii.y, radii.z}) : normalize(origin) * 6.0;
    Vec3d direction = from_inside ? Vec3d{unit(random), unit(random), unit(random)} : target - origin;
    return {origin, direction * (0.5 + std::abs(unit(random)))};  // not unit length on purpose
}

// Sign changes of the field along origin + t·direction on [t0, t1] by dense sampling (the crossings' midpoints).
inline std::vector<double> sampled_crossings(const Superquadric& s, const Vec3d& origin, const Vec3d& direction,
                                             double t0, double t1, int samples = 20000) {
    std::vector<double> found;
    double previous_t = t0;
    bool previous_inside = s.field(origin + direction * t0) < 0;
    for (int i = 1; i <= samples; ++i) {
        const double t = t0 + (t1 - t0) * i / samples;
        const bool inside = s.field(origin + direction * t) < 0;
        if (inside != previous_inside) found.push_back(0.5 * (previous_t + t));
        previous_t = t;
        previous_inside = inside;
    }
    return found;
}

}  // namespace isotrace::superquadric_test
