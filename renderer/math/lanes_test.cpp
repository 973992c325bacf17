// Lanes must round and compare exactly as the scalar operations they stand for: the packet queries' traceability
// test and the sphere prefilter give the one-ray answers only if they do.
#include "renderer/math/lanes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace isotrace {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }

TEST(Lanes, MinMaxAndAbsAreTheScalarOnesLaneByLane) {
    const float as[] = {1.0f, -2.0f, kNaN, 3.0f, -0.0f, 0.0f, kInf, -kInf};
    const float bs[] = {2.0f, -3.0f, 1.0f, kNaN, 0.0f, -0.0f, 5.0f, kNaN};
    FloatLanes a, b;
    for (int i = 0; i < kLanes; ++i) a[i] = as[i % 8] * float(1 + i / 8), b[i] = bs[i % 8] / float(1 + i / 8);
    const FloatLanes lo = min(a, b), hi = max(a, b), magnitude = abs(a);
    for (int i = 0; i < kLanes; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(bits(lo[i]), bits(std::min(a[i], b[i])));
        EXPECT_EQ(bits(hi[i]), bits(std::max(a[i], b[i])));
        EXPECT_EQ(bits(magnitude[i]), bits(std::abs(a[i])));
    }
}

TEST(Lanes, MasksSelectAndCount) {
    FloatLanes v;
    IntLanes parity;
    unsigned odd_bits = 0;
    for (int i = 0; i < kLanes; ++i) v[i] = float(i), parity[i] = i % 2, odd_bits |= unsigned(i % 2) << i;
    const IntLanes odd = parity != 0;
    EXPECT_EQ(lane_bits(odd), odd_bits);
    EXPECT_EQ(lane_bits(v == float(kLanes - 1)), 1u << (kLanes - 1));
    EXPECT_EQ(lane_bits(v < 0.0f), 0u);
    const FloatLanes picked = select(odd, v, splat(-1.0f));
    for (int i = 0; i < kLanes; ++i) EXPECT_EQ(picked[i], i % 2 ? float(i) : -1.0f);
}

// A lane mask from bits and back.
TEST(Lanes, MaskOfBitsIsTheirLanes) {
    for (unsigned bits = 0; bits < 256; ++bits) {
        const IntLanes mask = lanes_of_bits(bits);
        for (int lane = 0; lane < kLanes; ++lane) EXPECT_EQ(mask[lane], (bits >> lane & 1u) ? -1 : 0) << bits;
        EXPECT_EQ(lane_bits(mask), bits);
    }
}

}  // namespace
}  // namespace isotrace
