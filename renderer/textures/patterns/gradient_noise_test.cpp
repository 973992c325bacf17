#include "renderer/textures/patterns/gradient_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "renderer/textures/patterns/pattern_test_support.h"

namespace isotrace {
namespace {

TEST(GradientNoise, IsZeroAtLatticePoints) {
    for (const std::uint32_t seed : {0u, 1u, 77u, 0xffffffffu})
        for (int x = -4; x <= 4; ++x)
            for (int y = -4; y <= 4; ++y)
                for (int z = -4; z <= 4; ++z)
                    EXPECT_EQ(gradient_noise(Vec3f(float(x), float(y), float(z)), seed), 0.0f) << x << ' ' << y << ' ' << z;
    EXPECT_EQ(gradient_noise({1000, -12345, 7}, 3), 0.0f);
}

// Across a lattice plane in each axis a step of 1e-3 moves the value by at most 1e-2: the corners a point blends
// agree on both sides of a cell face (noise_basis_test checks random steps).
TEST(GradientNoise, IsContinuousAcrossCellFaces) {
    constexpr float kStep = 1e-3f, kLargestChange = 1e-2f;
    for (const Vec3f& p : random_points(20000, 20)) {
        for (int axis = 0; axis < 3; ++axis) {
            Vec3f below = p, above = p;
            below[axis] = std::round(p[axis]) - kStep / 2;
            above[axis] = std::round(p[axis]) + kStep / 2;
            ASSERT_LE(std::abs(gradient_noise(above, 5) - gradient_noise(below, 5)), kLargestChange) << axis;
        }
    }
}

// The formula's gradient against central differences of the noise (in double around float points, steps far above
// the float rounding), inside cells and across their faces, and at lattice points, where the noise is the corner's
// gradient dotted with the offset.
TEST(GradientNoise, TheGradientIsTheDerivativeOfTheNoise) {
    std::mt19937 random(4);
    std::uniform_real_distribution<float> coordinate(-20, 20);
    const float h = 1.0f / 256;  // a power of two: p ± h is exact for these coordinates
    for (int trial = 0; trial < 2000; ++trial) {
        Vec3f p{coordinate(random), coordinate(random), coordinate(random)};
        if (trial % 5 == 0) p.y = std::round(p.y);  // on a face between cells
        const std::uint32_t seed = static_cast<std::uint32_t>(trial % 3);
        const Vec3f g = gradient_noise_gradient(p, seed);
        for (int k = 0; k < 3; ++k) {
            Vec3f ahead = p, behind = p;
            ahead[k] += h;
            behind[k] -= h;
            const double difference = (double(gradient_noise(ahead, seed)) - gradient_noise(behind, seed)) / (2.0 * h);
            // The quotient's truncation error is below (h² / 6) max |n‴| (a few hundred at most for this noise).
            ASSERT_NEAR(g[k], difference, 5e-3) << trial << " axis " << k;
        }
    }
    const Vec3f lattice{3, -7, 12};
    const Vec3f g = gradient_noise_gradient(lattice, 9);
    const float step = 1.0f / 1024;
    for (int k = 0; k < 3; ++k) {
        Vec3f ahead = lattice;
        ahead[k] += step;
        EXPECT_NEAR(g[k], gradient_noise(ahead, 9) / step, 2e-3) << k;
    }
}

}  // namespace
}  // namespace isotrace
