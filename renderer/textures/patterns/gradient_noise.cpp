#include "renderer/textures/patterns/gradient_noise.h"

#include "renderer/textures/patterns/lattice.h"

namespace isotrace {
namespace {

// The largest |value| the unscaled sum reaches (every corner's gradient chosen to point at the point, maximised
// over the cell: noise_basis_test checks that the scaled field reaches neither beyond ±1 nor far short of it).
constexpr float kUnscaledExtreme = 1.03636f;  // 1.0363539, rounded up

// Perlin's quintic fade 6t^5 − 15t^4 + 10t^3: zero first and second derivatives at 0 and 1.
float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

float lerp(float t, float a, float b) {
    return a + t * (b - a);
}

}  // namespace

float gradient_noise(const Vec3f& p, std::uint32_t seed) {
    const LatticeCoordinate cx = lattice_coordinate(p.x), cy = lattice_coordinate(p.y), cz = lattice_coordinate(p.z);
    const float x = cx.offset, y = cy.offset, z = cz.offset;
    const std::uint32_t root = lattice_seed(seed);
    const std::uint32_t hx0 = lattice_hash(root, cx.cell), hx1 = lattice_hash(root, cx.cell + 1);
    const std::uint32_t h00 = lattice_hash(hx0, cy.cell), h01 = lattice_hash(hx0, cy.cell + 1);
    const std::uint32_t h10 = lattice_hash(hx1, cy.cell), h11 = lattice_hash(hx1, cy.cell + 1);
    const float u = fade(x), v = fade(y), w = fade(z);
    const auto corner = [&](std::uint32_t hxy, int dz, float gx, float gy) {
        return lattice_gradient_dot(lattice_hash(hxy, cz.cell + dz), gx, gy, z - static_cast<float>(dz));
    };
    const float near_z = lerp(v, lerp(u, corner(h00, 0, x, y), corner(h10, 0, x - 1, y)),
                              lerp(u, corner(h01, 0, x, y - 1), corner(h11, 0, x - 1, y - 1)));
    const float far_z = lerp(v, lerp(u, corner(h00, 1, x, y), corner(h10, 1, x - 1, y)),
                             lerp(u, corner(h01, 1, x, y - 1), corner(h11, 1, x - 1, y - 1)));
    return lerp(w, near_z, far_z) / kUnscaledExtreme;
}

}  // namespace isotrace
