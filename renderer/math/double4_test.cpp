// Double4's horizontal sums: lane_sums must give lane_sum's bits (the blob march's piece polynomials rely on it).
#include "renderer/math/double4.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

namespace isotrace {
namespace {

TEST(Double4, LaneSumsAreEachVectorsLaneSumBitForBit) {
    std::mt19937_64 random(5);
    // Magnitudes 2⁻⁴⁰ … 2⁴⁰ and both signs, so that the order of the additions shows in the last bits.
    std::uniform_real_distribution<double> exponent(-40, 40), sign(-1, 1);
    const auto lane = [&] { return (sign(random) < 0 ? -1.0 : 1.0) * std::exp2(exponent(random)); };
    int differing_orders = 0;  // sums where another order of the four additions gives other bits
    for (int trial = 0; trial < 10000; ++trial) {
        Double4 v[4];
        for (Double4& x : v) x = Double4{lane(), lane(), lane(), lane()};
        const Double4 sums = lane_sums(v[0], v[1], v[2], v[3]);
        for (int k = 0; k < 4; ++k) {
            ASSERT_EQ(std::bit_cast<std::uint64_t>(sums[k]), std::bit_cast<std::uint64_t>(lane_sum(v[k])));
            differing_orders += ((v[k][0] + v[k][2]) + (v[k][1] + v[k][3])) != lane_sum(v[k]);
        }
    }
    EXPECT_GT(differing_orders, 1000);  // the test can tell the orders apart
}

}  // namespace
}  // namespace isotrace
