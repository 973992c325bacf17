#include "renderer/textures/mip_pyramid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "renderer/math/rgb.h"

namespace isotrace {
namespace {

// A w x h image of one channel whose texel (x, y) is x + 10 y.
MipPyramid ramp(int w, int h, bool levels = true) {
    std::vector<float> texels;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) texels.push_back(float(x + 10 * y));
    return MipPyramid(w, h, 1, std::move(texels), levels);
}

float at(const MipPyramid& pyramid, float u, float v, float footprint = 0, WrapMode wrap = WrapMode::Repeat) {
    return pyramid.lookup<1>({u, v}, footprint, wrap)[0];
}

TEST(MipPyramid, LookupsAtTexelCentresAreTheTexels) {
    // Sizes that are powers of two, so that the centres' uv are exact floats.
    const MipPyramid pyramid = ramp(4, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 4; ++x)
            EXPECT_EQ(at(pyramid, (x + 0.5f) / 4, 1 - (y + 0.5f) / 8), float(x + 10 * y)) << x << ", " << y;
}

TEST(MipPyramid, LevelOneIsTheBoxAverage) {
    const MipPyramid pyramid = ramp(4, 4);
    ASSERT_EQ(pyramid.level_count(), 3);
    EXPECT_EQ(pyramid.width(1), 2);
    EXPECT_EQ(pyramid.height(1), 2);
    // Texel (1, 1) of level 1 averages texels x 2..3, y 2..3 of level 0.
    EXPECT_FLOAT_EQ(*pyramid.texel(1, 1, 1), (22 + 23 + 32 + 33) / 4.0f);
    EXPECT_FLOAT_EQ(*pyramid.texel(2, 0, 0), (0 + 1 + 2 + 3) / 4.0f + 15);  // the mean of all
}

TEST(MipPyramid, OddSizesAverageEveryTexel) {
    const MipPyramid pyramid = ramp(5, 1);
    ASSERT_EQ(pyramid.width(1), 2);
    EXPECT_FLOAT_EQ(*pyramid.texel(1, 0, 0), (0 + 1) / 2.0f);
    EXPECT_FLOAT_EQ(*pyramid.texel(1, 1, 0), (2 + 3 + 4) / 3.0f);  // the odd texel is not dropped
    EXPECT_EQ(pyramid.level_count(), 3);
    EXPECT_EQ(MipPyramid::reduced_texel_count(5, 1), 2u + 1u);
    EXPECT_EQ(MipPyramid::reduced_texel_count(4, 4), 4u + 1u);
}

TEST(MipPyramid, FootprintsPickLevelsAndBlendBetweenThem) {
    const MipPyramid pyramid = ramp(4, 4);
    const float u = 0.375f, v = 0.375f;  // inside texel (1, 2), at level 1 between texel centres
    const float level0 = pyramid.bilinear<1>(0, {u, v}, WrapMode::Repeat)[0];
    const float level1 = pyramid.bilinear<1>(1, {u, v}, WrapMode::Repeat)[0];
    const float level2 = *pyramid.texel(2, 0, 0);
    EXPECT_EQ(at(pyramid, u, v, 1), level0);  // one texel or less: level 0 alone
    EXPECT_EQ(at(pyramid, u, v, 2), level1);
    EXPECT_FLOAT_EQ(at(pyramid, u, v, std::sqrt(2.0f)), 0.5f * (level0 + level1));  // halfway in log2
    EXPECT_EQ(at(pyramid, u, v, 1000), level2);  // beyond the coarsest level
    EXPECT_EQ(at(pyramid, u, v, NAN), level0);
}

// The lookup that ImageTexture and ColourSource made before mip levels, written out: renders with a footprint of 0
// must not change by a bit.
Rgb former_bilinear(const std::vector<float>& rgb, int width, int height, std::array<float, 2> uv) {
    const auto texel = [&](int x, int y) {
        x %= width;
        y %= height;
        if (x < 0) x += width;
        if (y < 0) y += height;
        const float* p = rgb.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
        return Rgb{p[0], p[1], p[2]};
    };
    const float x = uv[0] * float(width) - 0.5f;
    const float y = (1.0f - uv[1]) * float(height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    const int x0 = int(fx), y0 = int(fy);
    return texel(x0, y0) * ((1 - tx) * (1 - ty)) + texel(x0 + 1, y0) * (tx * (1 - ty)) +
           texel(x0, y0 + 1) * ((1 - tx) * ty) + texel(x0 + 1, y0 + 1) * (tx * ty);
}

TEST(MipPyramid, FootprintZeroIsTheFormerBilinearRepeatLookup) {
    const int w = 7, h = 5;
    std::vector<float> rgb;
    for (int i = 0; i < w * h * 3; ++i) rgb.push_back(std::sin(float(i) * 1.7f) * 0.5f + 0.5f);
    const MipPyramid pyramid(w, h, 3, rgb, true);
    for (int i = 0; i < 400; ++i) {
        const std::array<float, 2> uv{std::sin(float(i) * 0.37f) * 3.1f, std::cos(float(i) * 0.91f) * 2.3f + 0.01f * float(i)};
        const std::array<float, 3> now = pyramid.lookup<3>(uv, 0, WrapMode::Repeat);
        const Rgb before = former_bilinear(rgb, w, h, uv);
        ASSERT_EQ(Rgb(now[0], now[1], now[2]), before) << uv[0] << ", " << uv[1];
    }
}

TEST(MipPyramid, WrapModes) {
    const MipPyramid pyramid = ramp(4, 1);
    const float v = 0.5f;
    // Beyond the right edge by half a texel: repeat wraps to texel 0, clamp stays on 3, mirror reflects to 3.
    EXPECT_EQ(at(pyramid, 1.125f, v, 0, WrapMode::Repeat), 0.0f);
    EXPECT_EQ(at(pyramid, 1.125f, v, 0, WrapMode::Clamp), 3.0f);
    EXPECT_EQ(at(pyramid, 1.125f, v, 0, WrapMode::Mirror), 3.0f);
    // Two texels beyond: texel 1 (repeat), still 3 (clamp), texel 2 (mirror).
    EXPECT_EQ(at(pyramid, 1.375f, v, 0, WrapMode::Repeat), 1.0f);
    EXPECT_EQ(at(pyramid, 1.375f, v, 0, WrapMode::Clamp), 3.0f);
    EXPECT_EQ(at(pyramid, 1.375f, v, 0, WrapMode::Mirror), 2.0f);
    // Left of the image, and halfway between the last texel and what lies beyond it.
    EXPECT_EQ(at(pyramid, -0.125f, v, 0, WrapMode::Mirror), 0.0f);
    EXPECT_EQ(at(pyramid, -0.375f, v, 0, WrapMode::Mirror), 1.0f);
    EXPECT_EQ(at(pyramid, 1.0f, v, 0, WrapMode::Repeat), 1.5f);
    EXPECT_EQ(at(pyramid, 1.0f, v, 0, WrapMode::Clamp), 3.0f);
    EXPECT_EQ(at(pyramid, 1.0f, v, 0, WrapMode::Mirror), 3.0f);
    EXPECT_EQ(wrap_index(-9, 4, WrapMode::Mirror), 0);  // period 8: -8 .. -5 read 0 .. 3, -4 .. -1 read 3 .. 0
    EXPECT_EQ(wrap_index(-6, 4, WrapMode::Mirror), 2);
    EXPECT_EQ(wrap_index(-2147483647, 3, WrapMode::Repeat), 2);
}

TEST(MipPyramid, HugeAndNanCoordinatesStayInside) {
    const MipPyramid pyramid = ramp(4, 4);
    EXPECT_TRUE(std::isfinite(at(pyramid, 1e30f, -1e30f)));
    EXPECT_TRUE(std::isfinite(at(pyramid, NAN, 0.5f, 3, WrapMode::Mirror)));
}

TEST(MipPyramid, WithoutReducedLevelsOnlyLevelZero) {
    const MipPyramid pyramid = ramp(8, 8, false);
    EXPECT_EQ(pyramid.level_count(), 1);
    EXPECT_EQ(at(pyramid, 0.3f, 0.6f, 100), at(pyramid, 0.3f, 0.6f, 0));
}

}  // namespace
}  // namespace isotrace
