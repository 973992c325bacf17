// Counter messages: a rank's counters survive their message, and the sum over ranks adds every field.
#include "renderer/distributed/counter_messages.h"

#include <gtest/gtest.h>

namespace isotrace {
namespace {

CounterTotals example(std::uint64_t scale) {
    CounterTotals totals;
    totals.camera_rays = 10 * scale;
    totals.secondary_rays = 20 * scale;
    totals.shadow_rays = 30 * scale;
    totals.nan_samples = scale;
    totals.geometry["blobs"] = {4 * scale, 5 * scale, 6 * scale, true};
    totals.geometry["triangles"] = {0, 0, 7 * scale, false};
    totals.named["blobs.pieces"] = 8 * scale;
    return totals;
}

TEST(CounterMessages, RoundTrip) {
    const CounterTotals back = decode_counters(encode_counters(example(3)));
    EXPECT_EQ(back.total_rays(), 180u);
    EXPECT_EQ(back.nan_samples, 3u);
    ASSERT_EQ(back.geometry.size(), 2u);
    EXPECT_EQ(back.geometry.at("blobs").candidate_hits, 15u);
    EXPECT_TRUE(back.geometry.at("blobs").counts_tests);
    EXPECT_FALSE(back.geometry.at("triangles").counts_tests);
    EXPECT_EQ(back.named.at("blobs.pieces"), 24u);
}

TEST(CounterMessages, SumsAddEveryField) {
    CounterTotals sum = example(1);
    CounterTotals other = example(2);
    other.named["csg.spans"] = 5;
    add_counters(sum, other);
    EXPECT_EQ(sum.camera_rays, 30u);
    EXPECT_EQ(sum.shadow_rays, 90u);
    EXPECT_EQ(sum.nan_samples, 3u);
    EXPECT_EQ(sum.geometry.at("blobs").tests, 12u);
    EXPECT_EQ(sum.geometry.at("triangles").closest_hits, 21u);
    EXPECT_EQ(sum.named.at("blobs.pieces"), 24u);
    EXPECT_EQ(sum.named.at("csg.spans"), 5u);
}

}  // namespace
}  // namespace isotrace
