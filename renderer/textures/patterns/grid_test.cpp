#include "renderer/textures/patterns/grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "renderer/textures/patterns/pattern_test_support.h"

namespace isotrace {
namespace {

TEST(Grid, OnLinesAndBetween) {
    EXPECT_EQ(grid({1.0f, 0.5f, 0.5f}, 0.1f, 0), 1.0f);
    EXPECT_EQ(grid({0.5f, -3.0f, 0.5f}, 0.1f, 0), 1.0f);
    EXPECT_EQ(grid({0.5f, 0.5f, 2.04f}, 0.1f, 0), 1.0f);
    EXPECT_EQ(grid({0.5f, 0.5f, 1.96f}, 0.1f, 0), 1.0f);
    EXPECT_EQ(grid({0.5f, 0.5f, 0.5f}, 0.1f, 0), 0.0f);
    EXPECT_EQ(grid({0.5f, 0.5f, 2.06f}, 0.1f, 0), 0.0f);
    EXPECT_EQ(grid({-0.3f, 7.7f, 0.2f}, 0.1f, 0), 0.0f);
    EXPECT_EQ(grid_2d({3.0f, 0.5f}, 0.1f, 0), 1.0f);
    EXPECT_EQ(grid_2d({0.5f, -0.97f}, 0.1f, 0), 1.0f);
    EXPECT_EQ(grid_2d({0.5f, 0.5f}, 0.1f, 0), 0.0f);
    EXPECT_EQ(grid_2d({0.5f, 0.5f}, 1.0f, 0), 1.0f);
    EXPECT_EQ(grid_2d({0.0f, 0.0f}, 0.0f, 0), 0.0f);
}

// A wide footprint gives the lines' coverage everywhere; a footprint of 0 leaves point samples.
TEST(Grid, WideFootprintsGiveTheCoverage) {
    constexpr float kWidth = 0.1f;
    const double coverage_3d = 1 - std::pow(1 - kWidth, 3), coverage_2d = 1 - std::pow(1 - kWidth, 2);
    const auto points = random_points(20000, 50);
    const Moments sharp = moments(points, [](const Vec3f& p) { return grid(p, kWidth, 0); });
    const Moments wide = moments(points, [](const Vec3f& p) { return grid(p, kWidth, 10); });
    EXPECT_NEAR(sharp.mean, coverage_3d, 0.01);
    EXPECT_NEAR(wide.minimum, coverage_3d, 2e-3);
    EXPECT_NEAR(wide.maximum, coverage_3d, 2e-3);
    const Moments wide_2d = moments(points, [](const Vec3f& p) { return grid_2d({p.x, p.y}, kWidth, 10); });
    EXPECT_NEAR(wide_2d.minimum, coverage_2d, 2e-3);
    EXPECT_NEAR(wide_2d.maximum, coverage_2d, 2e-3);
    for (const Vec3f& p : points) {
        const float value = grid(p, kWidth, 0);
        ASSERT_TRUE(value == 0 || value == 1);
    }
    EXPECT_FLOAT_EQ(grid({0.3f, 0.2f, 0.1f}, kWidth, std::numeric_limits<float>::infinity()), float(coverage_3d));
}

// The filtered value is the mean of point samples over the footprint's cube (square in 2-D), taken by brute force.
TEST(Grid, FilterIsTheBoxMean) {
    for (const float footprint : {0.07f, 0.3f, 1.7f}) {
        for (const Vec3f& p : random_points(5, 3, 7)) {
            const auto [mean_2d, mean_3d] = brute_force_box_means(
                [](std::array<float, 2> uv) { return grid_2d(uv, 0.2f, 0); }, [](const Vec3f& q) { return grid(q, 0.2f, 0); }, p,
                footprint);
            EXPECT_NEAR(grid(p, 0.2f, footprint), mean_3d, 0.03);
            EXPECT_NEAR(grid_2d({p.x, p.y}, 0.2f, footprint), mean_2d, 0.03);
        }
    }
}

TEST(Grid, NonFiniteInputsGiveValuesInRange) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN(), kInfinity = std::numeric_limits<float>::infinity();
    for (const float width : {0.1f, kNaN, -1.0f, 5.0f})
        for (const float footprint : {0.0f, 0.5f, kNaN, kInfinity}) {
            const float value = grid({kNaN, kInfinity, 0.4f}, width, footprint);
            EXPECT_TRUE(value >= 0 && value <= 1) << value;
        }
}

}  // namespace
}  // namespace isotrace
