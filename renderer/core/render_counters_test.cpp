#include "renderer/core/render_counters.h"

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <thread>
#include <vector>

namespace isotrace {
namespace {

// The counters are process-wide; every test starts from zero.
class RenderCounters : public ::testing::Test {
protected:
    void SetUp() override { counters::reset(); }
    void TearDown() override { counters::reset(); }
};

TEST_F(RenderCounters, CountsOfOneThreadAreExact) {
    for (int i = 0; i < 3; ++i) counters::count_ray(RayKind::Camera);
    for (int i = 0; i < 5; ++i) counters::count_ray(RayKind::Secondary);
    for (int i = 0; i < 7; ++i) counters::count_ray(RayKind::Shadow);
    counters::count_nan_sample();
    counters::count_nan_sample();
    const CounterTotals totals = counters::totals();
    EXPECT_EQ(totals.camera_rays, 3u);
    EXPECT_EQ(totals.secondary_rays, 5u);
    EXPECT_EQ(totals.shadow_rays, 7u);
    EXPECT_EQ(totals.total_rays(), 15u);
    EXPECT_EQ(totals.nan_samples, 2u);
}

TEST_F(RenderCounters, CountsFromSeveralThreadsAddUpExactly) {
    const int slot = counters::geometry_type_slot("counters_test_threads", true);
    constexpr int kThreads = 8;
    constexpr int kPerThread = 20000;
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([slot, t] {
            for (int i = 0; i < kPerThread; ++i) {
                counters::count_ray(RayKind::Camera);
                if (i % 2 == 0) counters::count_ray(RayKind::Shadow);
                counters::count_test(slot);
                if (i % 4 == 0) counters::count_candidate_hit(slot);
                if (i % 8 == 0) counters::count_closest_hit(slot);
            }
            for (int i = 0; i < t; ++i) counters::count_nan_sample();
        });
    for (auto& thread : threads) thread.join();
    // The threads have exited: their counts must survive them.
    const CounterTotals totals = counters::totals();
    EXPECT_EQ(totals.camera_rays, std::uint64_t(kThreads) * kPerThread);
    EXPECT_EQ(totals.shadow_rays, std::uint64_t(kThreads) * kPerThread / 2);
    EXPECT_EQ(totals.secondary_rays, 0u);
    EXPECT_EQ(totals.nan_samples, std::uint64_t(0 + 1 + 2 + 3 + 4 + 5 + 6 + 7));
    const GeometryTypeCounts& geometry = totals.geometry.at("counters_test_threads");
    EXPECT_EQ(geometry.tests, std::uint64_t(kThreads) * kPerThread);
    EXPECT_EQ(geometry.candidate_hits, std::uint64_t(kThreads) * kPerThread / 4);
    EXPECT_EQ(geometry.closest_hits, std::uint64_t(kThreads) * kPerThread / 8);
    EXPECT_TRUE(geometry.counts_tests);
}

// Per-object counters add into their type's total when totals are read (the hot path counts each amount once):
// the total is the sum of its parts plus what was added to it directly, from every thread, and a part of a part
// reaches the top.
TEST_F(RenderCounters, PartsAddIntoTheirTotalWhenTotalsAreRead) {
    const int total = counters::named_counter_slot("counters_test.total");
    const int first = counters::named_counter_slot("counters_test[a].total", total);
    const int second = counters::named_counter_slot("counters_test[b].total", total);
    const int nested = counters::named_counter_slot("counters_test[b][x].total", second);
    EXPECT_EQ(counters::named_counter_slot("counters_test[a].total", total), first);  // registered once
    std::thread worker([&] {
        counters::add_to_named(std::array{first, second}, std::array<std::uint64_t, 2>{3, 5});
    });
    worker.join();
    counters::add_to_named(std::array{first, total, nested}, std::array<std::uint64_t, 3>{7, 11, 13});
    const CounterTotals totals = counters::totals();
    EXPECT_EQ(totals.named.at("counters_test[a].total"), 10u);
    EXPECT_EQ(totals.named.at("counters_test[b][x].total"), 13u);
    EXPECT_EQ(totals.named.at("counters_test[b].total"), 18u);
    EXPECT_EQ(totals.named.at("counters_test.total"), 39u);
    EXPECT_THROW(counters::named_counter_slot("counters_test.early", 100000), std::logic_error);
}

TEST_F(RenderCounters, ResetZeroesEveryCounterOfEveryThread) {
    const int slot = counters::geometry_type_slot("counters_test_reset", false);
    std::thread worker([slot] {
        counters::count_ray(RayKind::Secondary);
        counters::count_closest_hit(slot);
        counters::count_nan_sample();
    });
    worker.join();
    counters::count_ray(RayKind::Camera);
    counters::count_test(slot);
    ASSERT_EQ(counters::totals().total_rays(), 2u);

    counters::reset();
    const CounterTotals totals = counters::totals();
    EXPECT_EQ(totals.total_rays(), 0u);
    EXPECT_EQ(totals.nan_samples, 0u);
    const GeometryTypeCounts& geometry = totals.geometry.at("counters_test_reset");  // names survive a reset
    EXPECT_EQ(geometry.tests, 0u);
    EXPECT_EQ(geometry.closest_hits, 0u);

    counters::count_ray(RayKind::Shadow);  // counting continues after a reset
    EXPECT_EQ(counters::totals().shadow_rays, 1u);
}

TEST_F(RenderCounters, GeometrySlotsAreReusedByName) {
    const int a = counters::geometry_type_slot("counters_test_a", true);
    const int b = counters::geometry_type_slot("counters_test_b", false);
    EXPECT_NE(a, b);
    EXPECT_EQ(counters::geometry_type_slot("counters_test_a", true), a);
    EXPECT_EQ(counters::geometry_type_slot("counters_test_b", false), b);
    // The first registration decides whether the type counts its tests.
    EXPECT_EQ(counters::geometry_type_slot("counters_test_b", true), b);

    counters::count_candidate_hit(a);
    counters::count_candidate_hit(counters::geometry_type_slot("counters_test_a", true));
    const CounterTotals totals = counters::totals();
    EXPECT_EQ(totals.geometry.at("counters_test_a").candidate_hits, 2u);
    EXPECT_TRUE(totals.geometry.at("counters_test_a").counts_tests);
    EXPECT_EQ(totals.geometry.at("counters_test_b").candidate_hits, 0u);
    EXPECT_FALSE(totals.geometry.at("counters_test_b").counts_tests);
}

}  // namespace
}  // namespace isotrace
