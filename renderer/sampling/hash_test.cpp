#include "renderer/sampling/hash.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <unordered_set>

namespace isotrace {
namespace {

// Flipping any input bit must flip every output bit about half the time (strict avalanche criterion).
template <class UInt, class Mix>
void expect_avalanche(Mix mix) {
    constexpr int bits = sizeof(UInt) * 8;
    constexpr int trials = 4000;
    int flips[bits][bits] = {};
    UInt input = 12345;
    for (int trial = 0; trial < trials; ++trial) {
        input = static_cast<UInt>(mix64(static_cast<uint64_t>(input) + 0x9e3779b97f4a7c15ull));  // varied inputs
        const UInt reference = mix(input);
        for (int in = 0; in < bits; ++in) {
            const UInt changed = mix(static_cast<UInt>(input ^ (UInt{1} << in))) ^ reference;
            for (int out = 0; out < bits; ++out) flips[in][out] += (changed >> out) & 1u;
        }
    }
    for (int in = 0; in < bits; ++in) {
        for (int out = 0; out < bits; ++out) {
            EXPECT_NEAR(flips[in][out] / double(trials), 0.5, 0.06) << "input bit " << in << " output bit " << out;
        }
    }
}

TEST(Hash, Mix32Avalanches) { expect_avalanche<uint32_t>(mix32<uint32_t>); }
TEST(Hash, Mix64Avalanches) { expect_avalanche<uint64_t>(mix64); }

TEST(Hash, CombineDependsOnOrderAndEveryValue) {
    EXPECT_NE(hash_combine(1u, 2u), hash_combine(2u, 1u));
    EXPECT_NE(hash_combine(0u), hash_combine(0u, 0u));
    EXPECT_NE(hash_combine(7u, 0u, 0u), hash_combine(7u, 0u, 1u));
    EXPECT_EQ(hash_combine(3u, 4u, 5u), hash_combine(3u, 4u, 5u));
}

TEST(Hash, CombineHasNoCollisionsOnSmallTuples) {
    // Neighbouring pixels, samples and dimensions are exactly where a weak combine would collide.
    std::unordered_set<uint64_t> seen;
    for (uint32_t x = 0; x < 16; ++x)
        for (uint32_t y = 0; y < 16; ++y)
            for (uint32_t i = 0; i < 16; ++i)
                for (uint32_t d = 0; d < 16; ++d) seen.insert(hash_combine(x, y, i, d));
    EXPECT_EQ(seen.size(), 16u * 16u * 16u * 16u);
}

TEST(Hash, UnitFloatIsInHalfOpenIntervalAndExact) {
    EXPECT_EQ(uint_to_unit_float(0), 0.0f);
    EXPECT_LT(uint_to_unit_float(0xffffffffu), 1.0f);
    EXPECT_EQ(uint_to_unit_float(0xffffffffu), 1.0f - 0x1p-24f);
    EXPECT_EQ(uint_to_unit_float(0x80000000u), 0.5f);
    for (uint32_t v : {1u, 255u, 256u, 0x12345678u, 0xdeadbeefu}) {
        const float f = uint_to_unit_float(v);
        EXPECT_EQ(f * 0x1p24f, std::floor(f * 0x1p24f)) << v;  // a multiple of 2^-24: no rounding happened
        EXPECT_EQ(static_cast<uint32_t>(f * 0x1p24f), v >> 8) << v;
    }
}

}  // namespace
}  // namespace isotrace

namespace isotrace {
namespace {

TEST(Hash, ExtendingAPrefixEqualsCombiningEverything) {
    for (uint64_t seed : {0ull, 1ull, 0xdeadbeefcafeull})
        for (uint32_t x : {0u, 5u, 0xffffffffu}) {
            EXPECT_EQ(hash_extend(hash_combine(seed, x), 7u, 9u), hash_combine(seed, x, 7u, 9u));
            EXPECT_EQ(hash_extend(0, seed, x), hash_combine(seed, x));
        }
}

}  // namespace
}  // namespace isotrace
