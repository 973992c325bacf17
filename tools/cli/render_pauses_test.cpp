// Checkpoints and interim outputs share the render's pauses: the render pauses at the shorter interval and each
// task runs when its own interval of rendering has passed.
#include "tools/cli/render_pauses.h"

#include <gtest/gtest.h>

#include <string>

namespace isotrace::cli {
namespace {

TEST(RenderPauses, NoTaskLeavesTheRenderUnpaused) {
    RenderPauses pauses;
    RenderOptions options;
    pauses.install(options);
    EXPECT_FALSE(options.checkpoint_interval_seconds);
    EXPECT_FALSE(options.on_checkpoint);
}

TEST(RenderPauses, EachTaskRunsAtItsOwnIntervalOfTheShortestPauses) {
    RenderPauses pauses;
    std::string runs;
    pauses.add(3.0, [&](const Film&) { runs += "c"; });  // a checkpoint every 3 s
    pauses.add(0.1, [&](const Film&) { runs += "w"; });  // interim outputs every 0.1 s
    RenderOptions options;
    pauses.install(options);
    ASSERT_TRUE(options.checkpoint_interval_seconds);
    EXPECT_DOUBLE_EQ(*options.checkpoint_interval_seconds, 0.1);
    const Film film(FilmSettings{{2, 2}, {0, 0, 2, 2}, {}, false});
    std::string expected;
    for (int pause = 1; pause <= 60; ++pause) {
        options.on_checkpoint(film);
        if (pause % 30 == 0) expected += "c";  // 30 pauses of 0.1 s make 3 s, despite 0.1's rounding
        expected += "w";
    }
    EXPECT_EQ(runs, expected);
}

TEST(RenderPauses, ATaskWhoseIntervalIsNotAMultipleRunsAtTheFirstPauseAfterItAndKeepsItsRate) {
    RenderPauses pauses;
    int checkpoints = 0;
    pauses.add(2.0, [&](const Film&) {});
    pauses.add(5.0, [&](const Film&) { ++checkpoints; });
    const Film film(FilmSettings{{2, 2}, {0, 0, 2, 2}, {}, false});
    for (int pause = 0; pause < 2; ++pause) pauses.pause(film);  // 4 s
    EXPECT_EQ(checkpoints, 0);
    pauses.pause(film);  // 6 s: 1 s late
    EXPECT_EQ(checkpoints, 1);
    pauses.pause(film);  // 8 s
    EXPECT_EQ(checkpoints, 1);
    pauses.pause(film);  // 10 s: the second 5 s, on time again
    EXPECT_EQ(checkpoints, 2);
}

}  // namespace
}  // namespace isotrace::cli
