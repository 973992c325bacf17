#include "renderer/textures/patterns/simplex_noise.h"

#include <algorithm>

#include "renderer/textures/patterns/gradient_noise.h"
#include "renderer/textures/patterns/lattice.h"

namespace isotrace {
namespace {

constexpr float kSkew = 1.0f / 3.0f;    // to the lattice of simplices: (√4 − 1) / 3
constexpr float kUnskew = 1.0f / 6.0f;  // back: (1 − 1/√4) / 3

// A corner's kernel (r0² − |d|²)^4 reaches no lattice vertex but the simplex's own four with r0² = 1/2, so the field
// is continuous where the simplex changes (Gustavson's 0.6 reaches a little beyond and leaves small steps).
constexpr float kKernelRadiusSquared = 0.5f;

// The largest |value| of the unscaled sum (every corner's gradient chosen to point at the point, maximised over
// the simplex: noise_basis_test checks that the scaled field reaches neither beyond ±1 nor far short of it).
constexpr float kUnscaledExtreme = 0.0130072f;  // 0.01300716, rounded up

float corner_contribution(std::int32_t i, std::int32_t j, std::int32_t k, std::uint32_t seed, float x, float y,
                          float z) {
    const float t = std::max(kKernelRadiusSquared - (x * x + y * y + z * z), 0.0f);
    const float t2 = t * t;
    return t2 * t2 * lattice_gradient_dot(cell_hash(i, j, k, seed), x, y, z);
}

}  // namespace

float simplex_noise(const Vec3f& p, std::uint32_t seed) {
    const float px = lattice_clamp(p.x), py = lattice_clamp(p.y), pz = lattice_clamp(p.z);
    const float skew = (px + py + pz) * kSkew;
    const std::int32_t i = lattice_floor(px + skew), j = lattice_floor(py + skew), k = lattice_floor(pz + skew);
    const float fi = static_cast<float>(i), fj = static_cast<float>(j), fk = static_cast<float>(k);
    const float unskew = (fi + fj + fk) * kUnskew;
    const float x0 = px - (fi - unskew), y0 = py - (fj - unskew), z0 = pz - (fk - unskew);

    // The simplex is the one whose edges follow the offset's components from the largest to the smallest: its
    // second corner steps along the largest, its third along the two largest (ties go to x, then y).
    // (& and | rather than && and ||: no branches to mispredict.)
    const bool x_ge_y = x0 >= y0, x_ge_z = x0 >= z0, y_ge_z = y0 >= z0;
    const int i1 = x_ge_y & x_ge_z, j1 = !x_ge_y & y_ge_z, k1 = !x_ge_z & !y_ge_z;
    const int i2 = x_ge_y | x_ge_z, j2 = !x_ge_y | y_ge_z, k2 = !x_ge_z | !y_ge_z;
    const float sum =
        corner_contribution(i, j, k, seed, x0, y0, z0) +
        corner_contribution(i + i1, j + j1, k + k1, seed, x0 - i1 + kUnskew, y0 - j1 + kUnskew, z0 - k1 + kUnskew) +
        corner_contribution(i + i2, j + j2, k + k2, seed, x0 - i2 + 2 * kUnskew, y0 - j2 + 2 * kUnskew,
                            z0 - k2 + 2 * kUnskew) +
        corner_contribution(i + 1, j + 1, k + 1, seed, x0 - 1 + 3 * kUnskew, y0 - 1 + 3 * kUnskew,
                            z0 - 1 + 3 * kUnskew);
    return sum / kUnscaledExtreme;
}

}  // namespace isotrace
