// Work plans of distributed renders: every (pixel, sample index) in exactly one item, blocks aligned and chained
// in order, regions large but numerous enough, finished regions of a resumed film left out.
#include "renderer/distributed/work_plan.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

namespace isotrace {
namespace {

FilmSettings film_settings(PixelBounds crop) {
    FilmSettings s;
    s.raster = {crop.x1 + 3, crop.y1 + 2};
    s.crop = crop;
    return s;
}

// How often each (pixel, sample index) is covered by the items; samples of a tile item run from 0 (fresh film).
std::map<std::pair<int, int>, std::vector<int>> coverage(const std::vector<WorkItem>& items, std::uint32_t spp) {
    std::map<std::pair<int, int>, std::vector<int>> covered;
    for (const WorkItem& item : items)
        for (int y = item.region.y0; y < item.region.y1; ++y)
            for (int x = item.region.x0; x < item.region.x1; ++x) {
                std::vector<int>& counts = covered[{x, y}];
                counts.resize(spp);
                for (std::uint32_t s = item.first_sample; s < item.last_sample; ++s) ++counts[s];
            }
    return covered;
}

void expect_every_sample_once(const std::vector<WorkItem>& items, const PixelBounds& crop, std::uint32_t spp) {
    const auto covered = coverage(items, spp);
    EXPECT_EQ(std::int64_t(covered.size()), crop.area());
    for (const auto& [pixel, counts] : covered) {
        EXPECT_TRUE(pixel.first >= crop.x0 && pixel.first < crop.x1 && pixel.second >= crop.y0 && pixel.second < crop.y1);
        for (int c : counts) ASSERT_EQ(c, 1) << "pixel " << pixel.first << ", " << pixel.second;
    }
}

TEST(WorkPlan, TilesCoverEveryPixelOnceWithAtLeastTheRequestedCount) {
    const PixelBounds crop{3, 2, 3 + 130, 2 + 70};
    const Film film(film_settings(crop));
    const std::vector<WorkItem> items = plan_tiles(film, 16, 8, 8);
    expect_every_sample_once(items, crop, 8);
    EXPECT_GE(items.size(), 8u);
    EXPECT_LT(items.size(), 32u);  // the largest edge that still gives 8: not the 16-pixel tiles themselves (45)
    for (const WorkItem& item : items) {
        EXPECT_EQ(item.first_sample, 0u);
        EXPECT_FALSE(item.previous);
    }
}

TEST(WorkPlan, TilesOfAResumedFilmLeaveOutFinishedRegions) {
    const PixelBounds crop{0, 0, 64, 32};
    Film film(film_settings(crop));
    CameraSample sample;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            for (int s = 0; s < 4; ++s) film.add_sample(x, y, sample);
    film.add_sample(40, 3, sample);  // a pixel of an unfinished region
    const std::vector<WorkItem> items = plan_tiles(film, 32, 4, 2);  // two regions of 32x32
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].region.x0, 32);
}

TEST(WorkPlan, SampleBlocksCoverEverySampleOnceAlignedAndChained) {
    const PixelBounds crop{0, 0, 300, 500};  // 150 000 pixels: three bands
    const std::uint32_t first = Film::kSampleBlock, spp = 3 * Film::kSampleBlock + 7;
    const std::vector<WorkItem> items = plan_sample_blocks(crop, first, spp);
    ASSERT_EQ(items.size(), 3u * 3u);
    for (std::size_t i = 0; i < items.size(); ++i) {
        const WorkItem& item = items[i];
        EXPECT_LE(item.region.area(), kBandPixels);
        EXPECT_EQ(item.region.x0, crop.x0);
        EXPECT_EQ(item.region.x1, crop.x1);
        EXPECT_EQ(item.first_sample % Film::kSampleBlock, 0u);
        EXPECT_LE(item.last_sample - item.first_sample, Film::kSampleBlock);
        if (item.first_sample == first) {
            EXPECT_FALSE(item.previous);
        } else {
            ASSERT_TRUE(item.previous);
            EXPECT_EQ(items[*item.previous].last_sample, item.first_sample);
            EXPECT_EQ(items[*item.previous].region.y0, item.region.y0);
        }
    }
    // Samples before `first` belong to the resumed film, not to any item.
    const auto covered = coverage(items, spp);
    for (const auto& [pixel, counts] : covered)
        for (std::uint32_t s = 0; s < spp; ++s) ASSERT_EQ(counts[s], s < first ? 0 : 1);
    EXPECT_EQ(std::int64_t(covered.size()), crop.area());
}

TEST(WorkPlan, NoSamplesLeftMeansNoItems) {
    EXPECT_TRUE(plan_sample_blocks(PixelBounds{0, 0, 8, 8}, 64, 64).empty());
}

}  // namespace
}  // namespace isotrace
