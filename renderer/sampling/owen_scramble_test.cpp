#include "renderer/sampling/owen_scramble.h"

#include <gtest/gtest.h>

#include <vector>

#include "renderer/sampling/hash.h"

namespace isotrace {
namespace {

TEST(ReverseBits, ReversesAndIsAnInvolution) {
    EXPECT_EQ(reverse_bits(1u), 0x80000000u);
    EXPECT_EQ(reverse_bits(0x0000000fu), 0xf0000000u);
    EXPECT_EQ(reverse_bits(0x12345678u), 0x1e6a2c48u);
    for (uint32_t v : {0u, 3u, 0xdeadbeefu, 0xffffffffu}) EXPECT_EQ(reverse_bits(reverse_bits(v)), v);
}

// The defining property of a nested scramble: the top m output bits are a permutation of the top m input bits
// that ignores all lower bits, so dyadic intervals of length 2^-m are permuted as wholes.
TEST(NestedUniformScramble, PermutesDyadicIntervalsAsWholes) {
    constexpr int m = 8;
    for (uint32_t s = 0; s < 16; ++s) {
        const uint32_t seed = static_cast<uint32_t>(hash_combine(s));
        std::vector<int> hits(1 << m, 0);
        for (uint32_t prefix = 0; prefix < (1u << m); ++prefix) {
            const uint32_t base = prefix << (32 - m);
            const uint32_t image = nested_uniform_scramble(base, seed) >> (32 - m);
            ++hits[image];
            for (uint32_t low : {1u, 0x00abcdefu, 0x00ffffffu}) {
                EXPECT_EQ(nested_uniform_scramble(base | low, seed) >> (32 - m), image);
            }
        }
        for (int count : hits) EXPECT_EQ(count, 1);
    }
}

TEST(NestedUniformScramble, EveryBitIsFlippedHalfTheTimeOverSeeds) {
    constexpr int seeds = 8192;
    for (uint32_t x : {0u, 0x80000000u, 0x12345678u}) {
        int ones[32] = {};
        for (uint32_t s = 0; s < seeds; ++s) {
            const uint32_t y = nested_uniform_scramble(x, static_cast<uint32_t>(hash_combine(s, 99u)));
            for (int bit = 0; bit < 32; ++bit) ones[bit] += (y >> bit) & 1u;
        }
        for (int bit = 0; bit < 32; ++bit) EXPECT_NEAR(ones[bit] / double(seeds), 0.5, 0.04) << "bit " << bit;
    }
}

TEST(NestedUniformScramble, DifferentSeedsGiveDifferentPermutations) {
    const uint32_t x = 0x9abcdef0u;
    EXPECT_NE(nested_uniform_scramble(x, static_cast<uint32_t>(hash_combine(1u))),
              nested_uniform_scramble(x, static_cast<uint32_t>(hash_combine(2u))));
}

}  // namespace
}  // namespace isotrace
