#include "renderer/textures/patterns/checker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "renderer/textures/patterns/pattern_test_support.h"

namespace isotrace {
namespace {

TEST(Checker, KnownPoints) {
    EXPECT_EQ(checker({0.25f, 0.25f, 0.25f}, 0), 0.0f);
    EXPECT_EQ(checker({1.25f, 0.25f, 0.25f}, 0), 1.0f);
    EXPECT_EQ(checker({1.25f, 1.25f, 0.25f}, 0), 0.0f);
    EXPECT_EQ(checker({1.25f, 1.25f, 1.25f}, 0), 1.0f);
    EXPECT_EQ(checker({-0.25f, 0.25f, 0.25f}, 0), 1.0f);
    EXPECT_EQ(checker({-1.25f, -0.25f, 0.25f}, 0), 1.0f);
    EXPECT_EQ(checker({-1.25f, -0.25f, -0.25f}, 0), 0.0f);
    EXPECT_EQ(checker_2d({0.25f, 0.25f}, 0), 0.0f);
    EXPECT_EQ(checker_2d({1.25f, 0.25f}, 0), 1.0f);
    EXPECT_EQ(checker_2d({-0.75f, -5.5f}, 0), 1.0f);
}

// A footprint of 0 is a point sample (values in {0, 1}); one of 10 cells averages to ½ everywhere, with the mean
// over space unchanged.
TEST(Checker, FilteringKeepsTheMeanAndFlattensWideFootprints) {
    const auto points = random_points(20000, 50);
    const Moments sharp = moments(points, [](const Vec3f& p) { return checker(p, 0); });
    const Moments wide = moments(points, [](const Vec3f& p) { return checker(p, 10); });
    EXPECT_NEAR(sharp.mean, 0.5, 0.01);
    EXPECT_NEAR(sharp.standard_deviation, 0.5, 0.001);
    EXPECT_NEAR(wide.mean, 0.5, 1e-3);
    EXPECT_GT(wide.minimum, 0.499);
    EXPECT_LT(wide.maximum, 0.501);
    for (const Vec3f& p : points) {
        const float value = checker(p, 0);
        ASSERT_TRUE(value == 0 || value == 1);
        ASSERT_EQ(checker_2d({p.x, p.y}, 0), checker({p.x, p.y, 0.5f}, 0));
    }
    EXPECT_EQ(checker({0.3f, 0.2f, 0.1f}, std::numeric_limits<float>::infinity()), 0.5f);
}

// The filtered value is the mean of point samples over the footprint's cube (square in 2-D), taken by brute force.
TEST(Checker, FilterIsTheBoxMean) {
    for (const float footprint : {0.3f, 1.7f}) {
        for (const Vec3f& p : random_points(5, 3, 7)) {
            const auto [mean_2d, mean_3d] = brute_force_box_means(
                [](std::array<float, 2> uv) { return checker_2d(uv, 0); }, [](const Vec3f& q) { return checker(q, 0); }, p,
                footprint);
            EXPECT_NEAR(checker(p, footprint), mean_3d, 0.03);
            EXPECT_NEAR(checker_2d({p.x, p.y}, footprint), mean_2d, 0.03);
        }
    }
}

TEST(Checker, NonFiniteInputsGiveValuesInRange) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN(), kInfinity = std::numeric_limits<float>::infinity();
    for (const float footprint : {0.0f, 0.5f, kNaN, -1.0f}) {
        const float value = checker({kNaN, kInfinity, -kInfinity}, footprint);
        EXPECT_TRUE(value >= 0 && value <= 1) << value;
    }
}

}  // namespace
}  // namespace isotrace
