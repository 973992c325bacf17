#pragma once
// Sweeps with known shapes for the tests of this folder.
#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/sweep/key_section.h"

namespace isotrace::sweep_test {

inline std::vector<double> constant_radii(double r, int m = 16) { return std::vector<double>(std::size_t(m), r); }

// The radius of a circle of radius `radius` whose centre is offset by `offset` along the local x axis, seen from
// the section centre, at the m sample angles: e·cos θ + √(a² − e² sin² θ) (requires |offset| < radius).
inline std::vector<double> offset_circle_radii(double radius, double offset, int samples) {
    std::vector<double> radii;
    for (int j = 0; j < samples; ++j) {
        const double theta = 2 * std::numbers::pi * j / samples;
        const double s = offset * std::sin(theta);
        radii.push_back(offset * std::cos(theta) + std::sqrt(radius * radius - s * s));
    }
    return radii;
}

// A circular cylinder of radius r along +z from z = 0 to z = length, through `keys` key sections.
inline std::vector<KeySection> cylinder(double r, double length, int keys = 4) {
    std::vector<KeySection> k;
    for (int i = 0; i < keys; ++i) k.push_back({{0, 0, length * i / (keys - 1)}, Quaternion::identity(), constant_radii(r)});
    return k;
}

// Keys on a circle of radius `ring` in the xy plane from angle 0 to `sweep_degrees`, each section's normal along
// the circle's tangent and its local x axis pointing away from the circle's centre.
inline std::vector<KeySection> ring(double ring, double sweep_degrees, int keys, std::vector<double> radii) {
    std::vector<KeySection> k;
    for (int i = 0; i < keys; ++i) {
        const double degrees = sweep_degrees * i / (keys - 1), phi = degrees * std::numbers::pi / 180;
        k.push_back({{ring * std::cos(phi), ring * std::sin(phi), 0},
                     Quaternion::from_axis_angle({0, 0, 1}, degrees) * Quaternion::from_axis_angle({1, 0, 0}, -90),
                     radii});
    }
    return k;
}

// A bent, tapering tube with non-circular sections: a general test sweep.
inline std::vector<KeySection> bent_tube() {
    std::vector<KeySection> k;
    for (int i = 0; i < 5; ++i) {
        std::vector<double> radii;
        for (int j = 0; j < 12; ++j) radii.push_back((0.5 - 0.05 * i) * (1 + 0.2 * std::cos(2 * std::numbers::pi * j / 12)));
        k.push_back({{0.3 * i * i / 4.0, 0, 1.0 * i}, Quaternion::from_axis_angle({0, 1, 0}, 8.0 * i), radii});
    }
    return k;
}

}  // namespace isotrace::sweep_test
