// A timed run repeats its work until it has lasted its minimum time and reports the time per pass; without a
// minimum it takes one pass.
#include "tools/cli/ray_cast_timing.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace isotrace::cli {
namespace {

TEST(RayCastTiming, AShortRunRepeatsItsWorkUntilItLastsItsMinimumTime) {
    std::vector<int> calls(2, 0);
    const auto trace = [&](RayCastTiming& timing, std::size_t scene) {
        ++calls[scene];
        timing.ray_count = 1;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    };
    constexpr double kMinimum = 0.01;
    const std::vector<RayCastTiming> timings = time_taking_turns(2, 1, 3, trace, kMinimum);
    ASSERT_EQ(timings.size(), 2u);
    for (std::size_t scene = 0; scene < 2; ++scene) {
        const RayCastTiming& timing = timings[scene];
        ASSERT_EQ(timing.seconds.size(), 3u);
        ASSERT_EQ(timing.passes.size(), 3u);
        int passes = 0;
        for (std::size_t run = 0; run < 3; ++run) {
            // A call takes far less than the minimum: the run repeats it, and its time per pass times its passes
            // covers the minimum.
            EXPECT_GT(timing.passes[run], 1);
            EXPECT_LE(timing.passes[run], kMaxPasses);
            EXPECT_GE(timing.seconds[run] * timing.passes[run], kMinimum * (1 - 1e-12));
            passes += timing.passes[run];
        }
        EXPECT_EQ(calls[scene], passes);
    }
}

// Work that takes almost no time stops at the bound on passes, not at the minimum time.
TEST(RayCastTiming, ARunsPassesAreBounded) {
    const std::vector<RayCastTiming> timings =
        time_taking_turns(1, 1, 1, [](RayCastTiming& timing, std::size_t) { timing.ray_count = 1; }, 60.0);
    EXPECT_EQ(timings.front().passes, std::vector<int>{kMaxPasses});
}

TEST(RayCastTiming, WithoutAMinimumTimeARunTakesOnePass) {
    int calls = 0;
    const std::vector<RayCastTiming> timings =
        time_taking_turns(1, 1, 4, [&](RayCastTiming& timing, std::size_t) { ++calls, timing.ray_count = 1; });
    EXPECT_EQ(calls, 4);
    EXPECT_EQ(timings.front().passes, std::vector<int>(4, 1));
}

// The runs that are not counted are the first ones, of the seconds and of the passes alike.
TEST(RayCastTiming, TheWarmUpRunsAreTheFirstOnesDropped) {
    int call = 0;
    RayCastTiming timing = time_taking_turns(1, 1, kWarmUpRuns + 2, [&](RayCastTiming& t, std::size_t) {
        t.ray_count = 1;
        // The warm-up run is the slow one, as a first run that builds what the rays need.
        if (call++ < kWarmUpRuns) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }).front();
    drop_warm_up(timing);
    ASSERT_EQ(timing.seconds.size(), 2u);
    ASSERT_EQ(timing.passes.size(), 2u);
    for (double seconds : timing.seconds) EXPECT_LT(seconds, 0.02);
}

}  // namespace
}  // namespace isotrace::cli
