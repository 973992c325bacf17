#pragma once
// Warps from the unit square [0,1)^2 to common domains, with their densities. Directions are in a local
// frame whose z axis is the surface normal. Densities of directions are per unit solid angle.
#include <array>

#include "renderer/math/vec3.h"

namespace isotrace {

// Shirley-Chiu concentric map: area-preserving and low distortion, so square strata stay compact on the disk.
// Uniform on the unit disk (density 1/pi).
std::array<float, 2> square_to_uniform_disk_concentric(std::array<float, 2> u);

// Malley's method: a uniform disk point lifted to the hemisphere gives density cos(theta)/pi.
Vec3f square_to_cosine_hemisphere(std::array<float, 2> u);
float square_to_cosine_hemisphere_pdf(const Vec3f& direction);

Vec3f square_to_uniform_sphere(std::array<float, 2> u);
float square_to_uniform_sphere_pdf();

Vec3f square_to_uniform_hemisphere(std::array<float, 2> u);
float square_to_uniform_hemisphere_pdf(const Vec3f& direction);

// Barycentrics (b0, b1) of a uniform point on a triangle, b2 = 1 - b0 - b1 (Heitz 2019, "A Low-Distortion
// Map Between Triangle and Square": keeps strata compact, unlike the square-root map).
std::array<float, 2> square_to_uniform_triangle(std::array<float, 2> u);

}  // namespace isotrace
