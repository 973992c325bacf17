// Range images: the paper's 256 grey levels, near bright and far dark, and the 8-bit grey PNG.
#include "renderer/render/range_image.h"

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/image/image_reader.h"
#include "renderer/image/image_writer.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

DepthMap map_of(std::vector<float> depth) {
    DepthMap map;
    map.window = {0, 0, int(depth.size()), 1};
    map.depth = std::move(depth);
    return map;
}

TEST(DepthRangeImage, RangeOfHitsIgnoresMisses) {
    const auto range = depth_range_of_hits(map_of({3.5f, DepthMap::kNoHit, 2.0f, 7.25f}));
    ASSERT_TRUE(range);
    EXPECT_EQ(range->near, 2.0f);
    EXPECT_EQ(range->far, 7.25f);
    EXPECT_FALSE(depth_range_of_hits(map_of({DepthMap::kNoHit, DepthMap::kNoHit})));
}

// The other reading of eq. 11 (Z as the depth itself): near black, far and background white.
TEST(DepthRangeImage, NearDarkMapsNearTo0AndFarTo255) {
    const DepthRange range{2.0f, 6.0f, false};
    EXPECT_EQ(range_grey_level(2.0f, range), 0);
    EXPECT_EQ(range_grey_level(6.0f, range), 255);  // g = 256 clamps to 255
    EXPECT_EQ(range_grey_level(4.0f, range), 128);  // (4 − 2)·256/4
    EXPECT_EQ(range_grey_level(3.0f, range), 64);
    EXPECT_EQ(range_grey_level(DepthMap::kNoHit, range), 255);
    EXPECT_EQ(range_grey_level(3.0f, DepthRange{3.0f, 3.0f, false}), 0);
}

TEST(DepthRangeImage, MapsNearTo255AndFarTo0) {
    const DepthRange range{2.0f, 6.0f};
    EXPECT_EQ(range_grey_level(2.0f, range), 255);  // g = 256 clamps to 255
    EXPECT_EQ(range_grey_level(6.0f, range), 0);
    EXPECT_EQ(range_grey_level(4.0f, range), 128);  // (6 − 4)·256/4
    EXPECT_EQ(range_grey_level(5.0f, range), 64);
    EXPECT_EQ(range_grey_level(1.0f, range), 255);  // nearer than near
    EXPECT_EQ(range_grey_level(9.0f, range), 0);    // beyond far
    EXPECT_EQ(range_grey_level(DepthMap::kNoHit, range), 0);
    EXPECT_EQ(range_grey_level(3.0f, DepthRange{3.0f, 3.0f}), 255);
    // Levels decrease monotonically with depth.
    int previous = 256;
    for (float d = 2.0f; d <= 6.0f; d += 0.01f) {
        const int g = range_grey_level(d, range);
        EXPECT_LE(g, previous);
        previous = g;
    }
}

TEST(DepthRangeImage, WritesAnEightBitGreyImage) {
    const DepthMap map = map_of({2.0f, 4.0f, 6.0f, DepthMap::kNoHit});
    const std::vector<std::uint8_t> grey = range_image(map, *depth_range_of_hits(map));
    EXPECT_EQ(grey, (std::vector<std::uint8_t>{255, 128, 0, 0}));
    const testing::TemporaryDirectory directory("range");
    const auto path = directory / "range.png";
    write_grey8_image(path, 4, 1, grey, {});
    const DecodedImage back = read_image_file(path);
    EXPECT_EQ(back.header.channel_names, std::vector<std::string>{"Y"});
    EXPECT_EQ(back.header.file_type, PixelType::UInt8);
    std::vector<std::uint8_t> read;
    for (float v : back.pixels) read.push_back(std::uint8_t(std::lround(v * 255.0f)));  // 8-bit values read as v / 255
    EXPECT_EQ(read, grey);
    EXPECT_EQ(directory.entries(), std::vector<std::string>{"range.png"});  // no temporary left behind
}

}  // namespace
}  // namespace isotrace
