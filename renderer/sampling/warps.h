#pragma once
// Warps from the unit square [0,1)^2 to common domains, with their densities. Directions are in a local
// frame whose z axis is the surface normal. Densities of directions are per unit solid angle.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "renderer/math/vec3.h"

namespace isotrace {

// Shirley-Chiu concentric map: area-preserving and low distortion, so square strata stay compact on the disk.
// Uniform on the unit disk (density 1/pi). Inline, as are the cosine-weighted warps below: every diffuse bounce
// and every thin-lens camera ray takes one.
inline std::array<float, 2> square_to_uniform_disk_concentric(std::array<float, 2> u) {
    constexpr float kQuarterPi = std::numbers::pi_v<float> / 4.0f, kHalfPi = std::numbers::pi_v<float> / 2.0f;
    const float a = 2.0f * u[0] - 1.0f;
    const float b = 2.0f * u[1] - 1.0f;
    if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
    float r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = kQuarterPi * (b / a);
    } else {
        r = b;
        phi = kHalfPi - kQuarterPi * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

// Malley's method: a uniform disk point lifted to the hemisphere gives density cos(theta)/pi.
inline Vec3f square_to_cosine_hemisphere(std::array<float, 2> u) {
    const auto [x, y] = square_to_uniform_disk_concentric(u);
    return {x, y, std::sqrt(std::max(0.0f, 1.0f - x * x - y * y))};
}
inline float square_to_cosine_hemisphere_pdf(const Vec3f& direction) {
    return direction.z > 0.0f ? direction.z / std::numbers::pi_v<float> : 0.0f;
}

Vec3f square_to_uniform_sphere(std::array<float, 2> u);
float square_to_uniform_sphere_pdf();

Vec3f square_to_uniform_hemisphere(std::array<float, 2> u);
float square_to_uniform_hemisphere_pdf(const Vec3f& direction);

// Barycentrics (b0, b1) of a uniform point on a triangle, b2 = 1 - b0 - b1 (Heitz 2019, "A Low-Distortion
// Map Between Triangle and Square": keeps strata compact, unlike the square-root map).
std::array<float, 2> square_to_uniform_triangle(std::array<float, 2> u);

}  // namespace isotrace
