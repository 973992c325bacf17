#include "tools/cli/bench_statistics.h"

#include <gtest/gtest.h>

namespace isotrace::cli {
namespace {

TEST(BenchStatistics, MedianOfOddAndEvenCounts) {
    EXPECT_DOUBLE_EQ(median({3, 1, 2}), 2);
    EXPECT_DOUBLE_EQ(median({4, 1, 3, 2}), 2.5);
    EXPECT_DOUBLE_EQ(median({7}), 7);
    EXPECT_DOUBLE_EQ(median({}), 0);
}

TEST(BenchStatistics, SpreadIsTheFiveNumberSummary) {
    // Sorted 1..5: quartiles at positions 1 and 3 exactly.
    const Spread s = spread_of({5, 2, 4, 1, 3});
    EXPECT_DOUBLE_EQ(s.min, 1);
    EXPECT_DOUBLE_EQ(s.q1, 2);
    EXPECT_DOUBLE_EQ(s.median, 3);
    EXPECT_DOUBLE_EQ(s.q3, 4);
    EXPECT_DOUBLE_EQ(s.max, 5);
}

TEST(BenchStatistics, QuartilesInterpolateBetweenRuns) {
    // Sorted 10, 20, 30, 40: q1 at position 0.75 → 17.5, q3 at 2.25 → 32.5 (NumPy's default).
    const Spread s = spread_of({40, 10, 30, 20});
    EXPECT_DOUBLE_EQ(s.q1, 17.5);
    EXPECT_DOUBLE_EQ(s.median, 25);
    EXPECT_DOUBLE_EQ(s.q3, 32.5);
}

TEST(BenchStatistics, OneRunHasNoSpread) {
    const Spread s = spread_of({1.5});
    EXPECT_DOUBLE_EQ(s.min, 1.5);
    EXPECT_DOUBLE_EQ(s.q1, 1.5);
    EXPECT_DOUBLE_EQ(s.q3, 1.5);
    EXPECT_DOUBLE_EQ(s.max, 1.5);
    const Spread none = spread_of({});
    EXPECT_DOUBLE_EQ(none.max, 0);
}

TEST(BenchStatistics, SpeedupAndEfficiency) {
    EXPECT_DOUBLE_EQ(speedup(30, 10), 3);
    EXPECT_DOUBLE_EQ(parallel_efficiency(3, 4, 1), 0.75);
    // Relative to a base of 2 threads: 8 threads at 3x is 3 / 4 efficient.
    EXPECT_DOUBLE_EQ(parallel_efficiency(3, 8, 2), 0.75);
    EXPECT_DOUBLE_EQ(parallel_efficiency(1, 1, 1), 1);
    EXPECT_DOUBLE_EQ(speedup(5, 0), 0);
    EXPECT_DOUBLE_EQ(parallel_efficiency(2, 0, 1), 0);
}

}  // namespace
}  // namespace isotrace::cli
