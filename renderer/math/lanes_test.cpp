// Lanes must round and compare exactly as the scalar operations they stand for: the packet path tracer's bits
// depend on it.
#include "renderer/math/lanes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>

#include "renderer/math/sin_cos_quarter_pi.h"
#include "renderer/sampling/warps.h"

namespace isotrace {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }

TEST(Lanes, MinMaxSqrtAbsAndSignAreTheScalarOnesLaneByLane) {
    const float as[] = {1.0f, -2.0f, kNaN, 3.0f, -0.0f, 0.0f, kInf, -kInf};
    const float bs[] = {2.0f, -3.0f, 1.0f, kNaN, 0.0f, -0.0f, 5.0f, kNaN};
    FloatLanes a, b;
    for (int i = 0; i < kLanes; ++i) a[i] = as[i % 8] * float(1 + i / 8), b[i] = bs[i % 8] / float(1 + i / 8);
    const FloatLanes lo = min(a, b), hi = max(a, b), root = sqrt(abs(a)), s = sign_of(a);
    for (int i = 0; i < kLanes; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(bits(lo[i]), bits(std::min(a[i], b[i])));
        EXPECT_EQ(bits(hi[i]), bits(std::max(a[i], b[i])));
        EXPECT_EQ(bits(root[i]), bits(std::sqrt(std::abs(a[i]))));
        EXPECT_EQ(bits(s[i]), bits(std::copysign(1.0f, a[i])));
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
    EXPECT_TRUE(any(odd));
    EXPECT_FALSE(any(v < 0.0f));
    const FloatLanes picked = select(odd, v, splat(-1.0f));
    for (int i = 0; i < kLanes; ++i) EXPECT_EQ(picked[i], i % 2 ? float(i) : -1.0f);
    EXPECT_EQ(select(true, 1.0f, 2.0f), 1.0f);
}

// Within 1.25 ulp of the exact values on |x| <= pi/4 (every 4099th float of the range here; all of them when
// the polynomials were chosen).
TEST(SinCosQuarterPi, WithinAboutAnUlp) {
    const float limit = std::numbers::pi_v<float> / 4;
    int checked = 0;
    for (std::uint32_t u = 0; u <= bits(limit); u += 4099) {
        for (const float x : {std::bit_cast<float>(u), -std::bit_cast<float>(u)}) {
            float s, c;
            sin_cos_quarter_pi(x, s, c);
            const double exact_s = std::sin(double(x)), exact_c = std::cos(double(x));
            const double ulp_s = std::max(double(std::nextafter(std::abs(float(exact_s)), kInf) - std::abs(float(exact_s))),
                                          double(std::numeric_limits<float>::denorm_min()));
            const double ulp_c = std::nextafter(float(exact_c), kInf) - float(exact_c);
            ASSERT_LE(std::abs(s - exact_s), 1.25 * ulp_s) << x;
            ASSERT_LE(std::abs(c - exact_c), 1.25 * ulp_c) << x;
            ++checked;
        }
    }
    EXPECT_GT(checked, 200000);
}

// A lane mask from bits and back.
TEST(Lanes, MaskOfBitsIsTheirLanes) {
    for (unsigned bits = 0; bits < 256; ++bits) {
        const IntLanes mask = lanes_of_bits(bits);
        for (int lane = 0; lane < kLanes; ++lane) EXPECT_EQ(mask[lane], (bits >> lane & 1u) ? -1 : 0) << bits;
        EXPECT_EQ(lane_bits(mask), bits);
    }
}

// The concentric map on lanes gives the scalar map's bits, centre and diagonals included.
TEST(ConcentricDiskPoint, LanesGiveTheScalarBits) {
    std::mt19937 random(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int round = 0; round < 2000; ++round) {
        FloatLanes a, b;
        for (int i = 0; i < kLanes; ++i) a[i] = 2 * unit(random) - 1, b[i] = 2 * unit(random) - 1;
        if (round == 0) {
            const float edge_a[] = {0, 0.5f, -0.5f, 0.25f, -1, 0, 1e-30f, 0.75f};
            const float edge_b[] = {0, 0.5f, 0.5f, -0.25f, -1, 0.3f, 0, -0.75f};
            for (int i = 0; i < 8; ++i) a[i] = edge_a[i], b[i] = edge_b[i];
        }
        FloatLanes x, y;
        concentric_disk_point(a, b, x, y);
        for (int i = 0; i < kLanes; ++i) {
            float ex, ey;
            concentric_disk_point(a[i], b[i], ex, ey);
            ASSERT_EQ(bits(x[i]), bits(ex)) << a[i] << ", " << b[i];
            ASSERT_EQ(bits(y[i]), bits(ey)) << a[i] << ", " << b[i];
            EXPECT_LE(ex * ex + ey * ey, 1.0f + 1e-6f);
        }
    }
    float x, y;
    concentric_disk_point(0.0f, 0.0f, x, y);
    EXPECT_EQ(x, 0.0f);
    EXPECT_EQ(y, 0.0f);
}

}  // namespace
}  // namespace isotrace
