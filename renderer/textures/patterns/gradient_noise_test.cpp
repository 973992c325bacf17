#include "renderer/textures/patterns/gradient_noise.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace isotrace
