#include "renderer/textures/patterns/cellular_noise.h"

#include <cmath>
#include <limits>

#include "renderer/textures/patterns/lattice.h"
#include "renderer/textures/patterns/pattern_math.h"

namespace isotrace {
namespace {

float cell_random(std::uint32_t hash, std::uint32_t stream) {
    return uint_to_unit_float(hash_stream(hash, stream));
}

// The feature point's offset from its cell's corner.
Vec3f feature_offset(std::uint32_t hash, float jitter) {
    return {0.5f + jitter * (cell_random(hash, 1) - 0.5f), 0.5f + jitter * (cell_random(hash, 2) - 0.5f),
            0.5f + jitter * (cell_random(hash, 3) - 0.5f)};
}

float cell_value(std::uint32_t hash) {
    return cell_random(hash, 4);
}

// Means over space of F1, F2 and F2 − F1 at jitter 0, 1/8, …, 1, measured with this search (cellular_noise_test
// measures them again between the nodes); linear in between.
constexpr int kMeanNodes = 9;
constexpr float kF1Means[kMeanNodes] = {0.4802f, 0.4812f, 0.4831f, 0.4871f, 0.4922f, 0.4987f, 0.5059f, 0.5132f, 0.5205f};
constexpr float kF2Means[kMeanNodes] = {0.7027f, 0.7038f, 0.7061f, 0.7090f, 0.7114f, 0.7132f, 0.7146f, 0.7158f, 0.7169f};

float interpolate_means(const float (&means)[kMeanNodes], float jitter) {
    const float position = unit_clamp(jitter) * (kMeanNodes - 1);
    const int node = std::min(static_cast<int>(position), kMeanNodes - 2);
    const float t = position - static_cast<float>(node);
    return means[node] + t * (means[node + 1] - means[node]);
}

}  // namespace

Vec3f cellular_feature_point(std::array<std::int32_t, 3> cell, std::uint32_t seed, float jitter) {
    const Vec3f corner{static_cast<float>(cell[0]), static_cast<float>(cell[1]), static_cast<float>(cell[2])};
    return corner + feature_offset(cell_hash(cell[0], cell[1], cell[2], seed), unit_clamp(jitter));
}

float cellular_cell_value(std::array<std::int32_t, 3> cell, std::uint32_t seed) {
    return cell_value(cell_hash(cell[0], cell[1], cell[2], seed));
}

float cellular_mean(CellularOutput output, float jitter) {
    switch (output) {
        case CellularOutput::F1: return interpolate_means(kF1Means, jitter);
        case CellularOutput::F2: return interpolate_means(kF2Means, jitter);
        case CellularOutput::F2MinusF1: return interpolate_means(kF2Means, jitter) - interpolate_means(kF1Means, jitter);
        case CellularOutput::CellValue: break;
    }
    return 0.5f;
}

float cellular(const Vec3f& p, std::uint32_t seed, float jitter, CellularOutput output, float footprint) {
    const float fade = smoothstep(0.5f, 1.0f, footprint_or_zero(footprint));
    const float mean = cellular_mean(output, jitter);
    if (fade >= 1) return mean;

    const float clamped_jitter = unit_clamp(jitter);
    const LatticeCoordinate cx = lattice_coordinate(p.x), cy = lattice_coordinate(p.y), cz = lattice_coordinate(p.z);
    const std::uint32_t root = lattice_seed(seed);
    float f1_squared = std::numeric_limits<float>::max(), f2_squared = f1_squared;
    std::uint32_t nearest_hash = 0;
    for (int dx = -1; dx <= 1; ++dx) {
        const std::uint32_t hx = lattice_hash(root, cx.cell + dx);
        for (int dy = -1; dy <= 1; ++dy) {
            const std::uint32_t hxy = lattice_hash(hx, cy.cell + dy);
            for (int dz = -1; dz <= 1; ++dz) {
                const std::uint32_t hash = lattice_hash(hxy, cz.cell + dz);
                const Vec3f offset = feature_offset(hash, clamped_jitter);
                const Vec3f d{static_cast<float>(dx) + offset.x - cx.offset, static_cast<float>(dy) + offset.y - cy.offset,
                              static_cast<float>(dz) + offset.z - cz.offset};
                const float distance_squared = dot(d, d);
                if (distance_squared < f1_squared) {
                    f2_squared = f1_squared;
                    f1_squared = distance_squared;
                    nearest_hash = hash;
                } else if (distance_squared < f2_squared) {
                    f2_squared = distance_squared;
                }
            }
        }
    }
    float value = cell_value(nearest_hash);
    if (output != CellularOutput::CellValue) {
        const float f1 = std::sqrt(f1_squared), f2 = std::sqrt(f2_squared);
        value = output == CellularOutput::F1 ? f1 : output == CellularOutput::F2 ? f2 : f2 - f1;
    }
    return value + fade * (mean - value);
}

}  // namespace isotrace
