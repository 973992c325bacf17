#include "renderer/sampling/warps.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace isotrace {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// z = cos(theta) plus an azimuth give the direction; clamping guards sqrt against z slightly above 1.
Vec3f direction_from_cos_theta(float z, float phi) {
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace

Vec3f square_to_uniform_sphere(std::array<float, 2> u) {
    return direction_from_cos_theta(1.0f - 2.0f * u[0], 2.0f * kPi * u[1]);
}

float square_to_uniform_sphere_pdf() {
    return 1.0f / (4.0f * kPi);
}

std::array<float, 2> square_to_uniform_triangle(std::array<float, 2> u) {
    // Each half of the square is sheared onto one half of the triangle (split along b0 = b1).
    if (u[0] < u[1]) {
        const float b0 = 0.5f * u[0];
        return {b0, u[1] - b0};
    }
    const float b1 = 0.5f * u[1];
    return {u[0] - b1, b1};
}

}  // namespace isotrace
