#include "renderer/core/parallel_for.h"

#include <gtest/gtest.h>

#include <tbb/blocked_range.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "renderer/core/parallel_sort.h"

// Plain (non-atomic) reads and writes on both sides of the loop: under -fsanitize=thread these tests fail with a
// data-race report unless parallel_for announces the fork and the join (TBB's own synchronisation is invisible).
namespace isotrace {
namespace {

constexpr std::size_t kCount = 10000;
constexpr int kThreads = 4;

TEST(ParallelFor, IndexFormSeesTheCallersInputsAndTheCallerSeesEveryResult) {
    std::vector<std::size_t> input(kCount);
    std::iota(input.begin(), input.end(), std::size_t(0));
    std::vector<std::size_t> output(kCount, 0);
    tbb::task_arena(kThreads).execute([&] {
        parallel_for(std::size_t(0), kCount, [&](std::size_t i) { output[i] = 2 * input[i] + 1; });
    });
    for (std::size_t i = 0; i < kCount; ++i) ASSERT_EQ(output[i], 2 * i + 1) << i;
}

TEST(ParallelFor, IndexFormTakesAnyIntegerRange) {
    std::vector<int> visits(20, 0);
    parallel_for(-10, 10, [&](int y) { ++visits[std::size_t(y + 10)]; });
    for (int v : visits) EXPECT_EQ(v, 1);
}

TEST(ParallelFor, RangeFormKeepsTheGrainSizeAndPartitioner) {
    // simple_partitioner splits down to the grain size: with grain 1 (the tile renderer's) every chunk is one
    // element, with grain 8 no chunk is longer than 8. chunk_length is written once per chunk, at its start.
    for (const std::size_t grain : {std::size_t(1), std::size_t(8)}) {
        std::vector<std::size_t> chunk_length(kCount, 0);
        tbb::task_arena(kThreads).execute([&] {
            parallel_for(
                tbb::blocked_range<std::size_t>(0, kCount, grain),
                [&](const tbb::blocked_range<std::size_t>& range) { chunk_length[range.begin()] = range.size(); },
                tbb::simple_partitioner());
        });
        std::size_t covered = 0;
        for (std::size_t i = 0; i < kCount; i += chunk_length[i]) {
            ASSERT_GE(chunk_length[i], 1u) << "index " << i << " not covered by a chunk starting there";
            ASSERT_LE(chunk_length[i], grain);
            covered += chunk_length[i];
        }
        EXPECT_EQ(covered, kCount);
    }
}

TEST(ParallelFor, AnExceptionInABodyReachesTheCaller) {
    EXPECT_THROW(parallel_for(std::size_t(0), kCount,
                              [](std::size_t i) {
                                  if (i == kCount / 2) throw std::runtime_error("body failed");
                              }),
                 std::runtime_error);
}

TEST(ParallelSort, SortsIntegersWithRepeatedKeys) {
    std::vector<std::uint64_t> keys(kCount);
    for (std::size_t i = 0; i < kCount; ++i) keys[i] = (i * 7919) % 1000;  // every key 10 times, shuffled
    std::vector<std::uint64_t> expected = keys;
    std::sort(expected.begin(), expected.end());
    tbb::task_arena(kThreads).execute([&] { parallel_sort(keys.begin(), keys.end()); });
    EXPECT_EQ(keys, expected);
}

}  // namespace
}  // namespace isotrace
