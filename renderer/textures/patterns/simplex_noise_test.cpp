#include "renderer/textures/patterns/simplex_noise.h"

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/textures/patterns/pattern_test_support.h"

namespace isotrace {
namespace {

// Inside a skewed cube the simplex changes where two offsets are equal, on the planes x − y, y − z or x − z ∈ ℤ.
// Across them a step of 1e-5 moves the value by at most 1e-3: no corner outside the simplex reaches the point
// (with Gustavson's kernel radius² 0.6 one does, and the value jumps there).
TEST(SimplexNoise, IsContinuousAcrossSimplexFaces) {
    constexpr float kStep = 1e-5f;
    float largest = 0;
    for (const Vec3f& p : random_points(50000, 4)) {
        for (int axis = 0; axis < 3; ++axis) {
            const int other = (axis + 1) % 3;
            // Move p[axis] to just either side of p[other] + k, keeping every other coordinate.
            const float plane = p[other] + std::round(p[axis] - p[other]);
            Vec3f below = p, above = p;
            below[axis] = plane - kStep / 2;
            above[axis] = plane + kStep / 2;
            largest = std::max(largest, std::abs(simplex_noise(above, 8) - simplex_noise(below, 8)));
        }
    }
    EXPECT_LT(largest, 1e-3f);
}

}  // namespace
}  // namespace isotrace
