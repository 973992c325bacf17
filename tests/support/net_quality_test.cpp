#include "tests/support/net_quality.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace isotrace::test_support {
namespace {

TEST(NetTValue, HammersleyIsAZeroNet) {
    // (i / 2^m, radical inverse of i) is the classic (0,m,2)-net.
    for (int m : {1, 4, 7}) {
        const unsigned n = 1u << m;
        std::vector<std::array<double, 2>> points;
        for (unsigned i = 0; i < n; ++i) {
            unsigned reversed = 0;
            for (int bit = 0; bit < m; ++bit) reversed |= ((i >> bit) & 1u) << (m - 1 - bit);
            points.push_back({(i + 0.5) / n, (reversed + 0.5) / n});
        }
        EXPECT_EQ(net_t_value(points), 0) << "m=" << m;
    }
}

TEST(NetTValue, DiagonalIsPoorlyStratified) {
    // Points on the diagonal are stratified in each axis alone, never in squares: t = m - 1 for 2^m points.
    std::vector<std::array<double, 2>> points;
    for (int i = 0; i < 16; ++i) points.push_back({(i + 0.5) / 16, (i + 0.5) / 16});
    EXPECT_EQ(net_t_value(points), 3);
}

TEST(NetTValue, IdenticalPointsHaveMaximalT) {
    const std::vector<std::array<double, 2>> points(8, std::array<double, 2>{0.3, 0.3});
    EXPECT_EQ(net_t_value(points), 3);
}

TEST(NetTValue, RejectsInvalidInput) {
    const std::vector<std::array<double, 2>> three(3, std::array<double, 2>{0.1, 0.1});
    EXPECT_THROW(net_t_value(three), std::invalid_argument);
    const std::vector<std::array<double, 2>> outside(2, std::array<double, 2>{1.0, 0.1});
    EXPECT_THROW(net_t_value(outside), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace::test_support
