#include "renderer/core/render_counters.h"

#include <gtest/gtest.h>

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
