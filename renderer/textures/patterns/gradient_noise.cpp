#include "renderer/textures/patterns/gradient_noise.h"

#include "renderer/textures/patterns/lattice.h"

namespace isotrace {
namespace {

// Perlin's quintic fade 6t^5 − 15t^4 + 10t^3: zero first and second derivatives at 0 and 1.
float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

float lerp(float t, float a, float b) {
    return a + t * (b - a);
}

// The fade's derivative 30 t²(t − 1)².
float fade_slope(float t) {
    const float s = t * (t - 1);
    return 30.0f * s * s;
}

// Corner values blended by the three fades; corner (a, b, c) at index a + 2b + 4c.
float trilinear(const float (&fades)[3], const float (&v)[8]) {
    const auto along_x = [&](int bc) { return lerp(fades[0], v[2 * bc], v[2 * bc + 1]); };
    return lerp(fades[2], lerp(fades[1], along_x(0), along_x(1)), lerp(fades[1], along_x(2), along_x(3)));
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
    return lerp(w, near_z, far_z) / kGradientNoiseUnscaledExtreme;
}

Vec3f gradient_noise_gradient(const Vec3f& p, std::uint32_t seed) {
    const LatticeCoordinate c[3] = {lattice_coordinate(p.x), lattice_coordinate(p.y), lattice_coordinate(p.z)};
    const CellGradients gradients = cell_gradients(lattice_seed(seed), {c[0].cell, c[1].cell, c[2].cell});
    const auto& g = gradients.g;
    float dots[8];
    for (int corner = 0; corner < 8; ++corner) {
        const int a = corner & 1, b = (corner >> 1) & 1, d = corner >> 2;
        dots[corner] = g[corner][0] * (c[0].offset - a) + g[corner][1] * (c[1].offset - b) + g[corner][2] * (c[2].offset - d);
    }
    const float fades[3] = {fade(c[0].offset), fade(c[1].offset), fade(c[2].offset)};
    Vec3f gradient;
    for (int k = 0; k < 3; ++k) {
        // ∂n/∂x_k = fade′(x_k) × (the blend of the dots' differences across axis k) + the blend of the g_k.
        float across[8], partial[8];
        for (int corner = 0; corner < 8; ++corner) {
            across[corner] = dots[corner | (1 << k)] - dots[corner & ~(1 << k)];
            partial[corner] = g[corner][k];
        }
        float flat[3] = {fades[0], fades[1], fades[2]};
        flat[k] = 0;  // the differences do not depend on the corner's k bit: blend the k = 0 ones
        gradient[k] = (fade_slope(c[k].offset) * trilinear(flat, across) + trilinear(fades, partial)) / kGradientNoiseUnscaledExtreme;
    }
    return gradient;
}

CellGradients cell_gradients(std::uint32_t root, const std::int32_t (&cell)[3]) {
    CellGradients gradients;
    for (int corner = 0; corner < 8; ++corner) {
        const std::uint32_t hash =
            lattice_hash(lattice_hash(lattice_hash(root, cell[0] + (corner & 1)), cell[1] + ((corner >> 1) & 1)),
                         cell[2] + (corner >> 2));
        // The corner's gradient read off its dot product with the axes.
        for (int k = 0; k < 3; ++k) gradients.g[corner][k] = lattice_gradient_dot(hash, k == 0, k == 1, k == 2);
    }
    return gradients;
}

}  // namespace isotrace
