#include "renderer/textures/patterns/ramp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "renderer/textures/patterns/pattern_test_support.h"

namespace isotrace {
namespace {

TEST(Ramp, KnownValues) {
    EXPECT_EQ(ramp({-0.5f, 3, 3}, RampShape::Linear), 0.0f);
    EXPECT_EQ(ramp({0.25f, 3, 3}, RampShape::Linear), 0.25f);
    EXPECT_EQ(ramp({1.5f, 3, 3}, RampShape::Linear), 1.0f);
    EXPECT_EQ(ramp({0.5f, 0, 0}, RampShape::Smooth), 0.5f);
    EXPECT_FLOAT_EQ(ramp({0.25f, 0, 0}, RampShape::Smooth), 0.15625f);
    EXPECT_EQ(ramp({2, 0, 0}, RampShape::Smooth), 1.0f);
    EXPECT_EQ(ramp({0, 0, 0}, RampShape::Spherical), 1.0f);
    EXPECT_FLOAT_EQ(ramp({0, 0.6f, 0}, RampShape::Spherical), 0.4f);
    EXPECT_EQ(ramp({0, 3, 4}, RampShape::Spherical), 0.0f);
    EXPECT_EQ(ramp({1, 0, 5}, RampShape::Radial), 0.0f);
    EXPECT_FLOAT_EQ(ramp({0, 1, 5}, RampShape::Radial), 0.25f);
    EXPECT_FLOAT_EQ(ramp({-1, 0, 5}, RampShape::Radial), 0.5f);
    EXPECT_FLOAT_EQ(ramp({0, -1, 5}, RampShape::Radial), 0.75f);
}

TEST(Ramp, StaysInUnitRange) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN(), kInfinity = std::numeric_limits<float>::infinity();
    for (const RampShape shape : {RampShape::Linear, RampShape::Smooth, RampShape::Spherical, RampShape::Radial}) {
        for (const Vec3f& p : random_points(10000, 3)) {
            const float value = ramp(p, shape);
            ASSERT_TRUE(value >= 0 && value <= 1) << value;
        }
        EXPECT_EQ(ramp({kNaN, kNaN, kNaN}, shape), 0.0f);
        EXPECT_TRUE(std::isfinite(ramp({kInfinity, -kInfinity, 0}, shape)));
    }
    EXPECT_LT(ramp({1, -1e-30f, 0}, RampShape::Radial), 1.0f);  // just below the seam
}

}  // namespace
}  // namespace isotrace
