#include "renderer/image_compare/error_map.h"

#include <gtest/gtest.h>

namespace isotrace {
namespace {

TEST(ErrorMap, MagmaLikeRunsFromNearBlackToPaleYellow) {
    const auto low = magma_like(0), high = magma_like(1);
    EXPECT_LT(low[0] + low[1] + low[2], 10);
    EXPECT_GT(high[0], 240);
    EXPECT_GT(high[1], 240);
    EXPECT_GT(high[2], 180);
    EXPECT_EQ(magma_like(-1), low);  // clamped
    EXPECT_EQ(magma_like(7), high);
}

TEST(ErrorMap, BrightnessGrowsWithTheError) {
    int previous = -1;
    for (int i = 0; i <= 64; ++i) {
        const auto c = magma_like(i / 64.0);
        const int brightness = 2126 * c[0] + 7152 * c[1] + 722 * c[2];
        EXPECT_GE(brightness, previous) << i;
        previous = brightness;
    }
}

TEST(ErrorMap, FalseColourScalesByTheFullScale) {
    const std::vector<std::uint8_t> bytes = false_colour({0.0f, 2.0f, 4.0f}, 4.0);
    ASSERT_EQ(bytes.size(), 9u);
    const auto middle = magma_like(0.5), top = magma_like(1);
    EXPECT_EQ(bytes[3], middle[0]);
    EXPECT_EQ(bytes[8], top[2]);
    EXPECT_THROW(false_colour({1.0f}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
