#pragma once
// Warps from the unit square [0,1)^2 to common domains, with their densities. Directions are in a local
// frame whose z axis is the surface normal. Densities of directions are per unit solid angle.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "renderer/math/sin_cos_quarter_pi.h"
#include "renderer/math/vec3.h"

namespace isotrace {

// Shirley-Chiu concentric map: area-preserving and low distortion, so square strata stay compact on the disk.
// Uniform on the unit disk (density 1/pi). (a, b) = 2u - 1 in [-1, 1)^2; the point is at radius r = the larger of
// |a|, |b| (signed), pi/4 * (smaller / larger) from that axis.
inline void concentric_disk_point(float a, float b, float& x, float& y) {
    constexpr float kQuarterPi = std::numbers::pi_v<float> / 4.0f;
    const bool a_major = std::abs(a) > std::abs(b);
    const float r = a_major ? a : b;
    // r = 0 only at the centre, where the point is (0, 0) whatever the angle.
    const float angle = kQuarterPi * (r != 0.0f ? (a_major ? b : a) / r : 0.0f);
    float sine, cosine;
    sin_cos_quarter_pi(angle, sine, cosine);
    x = r * (a_major ? cosine : sine);
    y = r * (a_major ? sine : cosine);
}

// Inline, as are the cosine-weighted warps below: every diffuse bounce and every thin-lens camera ray takes one.
inline std::array<float, 2> square_to_uniform_disk_concentric(std::array<float, 2> u) {
    float x, y;
    concentric_disk_point(2.0f * u[0] - 1.0f, 2.0f * u[1] - 1.0f, x, y);
    return {x, y};
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

// Barycentrics (b0, b1) of a uniform point on a triangle, b2 = 1 - b0 - b1 (Heitz 2019, "A Low-Distortion
// Map Between Triangle and Square": keeps strata compact, unlike the square-root map).
std::array<float, 2> square_to_uniform_triangle(std::array<float, 2> u);

}  // namespace isotrace
