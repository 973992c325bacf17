#include "renderer/math/branch_free.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

namespace isotrace {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The values the blob march passes: signed, zero of both signs, tiny, huge, infinite.
const std::vector<double> kValues{-kInfinity, -1e300, -2.5, -1e-310, -0.0, 0.0, 1e-310, 0.75, 1.0, 3.0, 1e300,
                                  kInfinity};

TEST(BranchFree, MinAndMaxAgreeWithTheStandardOnesBitForBit) {
    for (const double a : kValues)
        for (const double b : kValues) {
            EXPECT_EQ(std::bit_cast<std::uint64_t>(min_branch_free(a, b)), std::bit_cast<std::uint64_t>(std::min(b, a)))
                << a << " " << b;
            EXPECT_EQ(std::bit_cast<std::uint64_t>(max_branch_free(a, b)), std::bit_cast<std::uint64_t>(std::max(b, a)))
                << a << " " << b;
        }
}

TEST(BranchFree, ClampByMaxThenMinKeepsAVertexInsideAndMovesOneOutsideToTheNearerEnd) {
    EXPECT_EQ(min_branch_free(max_branch_free(0.5, 0.0), 1.0), 0.5);
    EXPECT_EQ(min_branch_free(max_branch_free(-3.0, 0.0), 1.0), 0.0);
    EXPECT_EQ(min_branch_free(max_branch_free(7.0, 0.0), 1.0), 1.0);
    EXPECT_EQ(min_branch_free(max_branch_free(-kInfinity, 0.25), 1.0), 0.25);  // no vertex: the start
}

TEST(BranchFree, ZeroUnlessLessKeepsTheValueOnlyWhenTheTestHolds) {
    for (const double a : kValues)
        for (const double b : kValues) {
            const double expected = a < b ? 2.5 : 0.0;
            EXPECT_EQ(std::bit_cast<std::uint64_t>(zero_unless_less(2.5, a, b)), std::bit_cast<std::uint64_t>(expected))
                << a << " " << b;
        }
    EXPECT_EQ(zero_unless_less(-4.0, 0.5, 1.0), -4.0);
    // NaN compares false: the value is dropped, as `a < b ? value : 0` drops it.
    EXPECT_EQ(std::bit_cast<std::uint64_t>(zero_unless_less(1.0, std::nan(""), 1.0)), std::bit_cast<std::uint64_t>(0.0));
}

}  // namespace
}  // namespace isotrace
