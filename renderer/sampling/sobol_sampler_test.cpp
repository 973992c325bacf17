#include "renderer/sampling/sobol_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "renderer/sampling/hash.h"
#include "renderer/sampling/independent_sampler.h"
#include "renderer/sampling/owen_scramble.h"
#include "renderer/sampling/sobol.h"
#include "tests/support/chi_square.h"
#include "tests/support/net_quality.h"

namespace isotrace {
namespace {

using Points = std::vector<std::array<double, 2>>;

const PixelSampleKey kPixels[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {17, 923, 0}, {4095, 2160, 0}, {0xffffffffu, 5, 0}};

// Samples first_index .. first_index + 2^m - 1 of a pixel in the given pair of dimensions.
Points pixel_pair(const Sampler& sampler, PixelSampleKey pixel, uint32_t first_dimension, int m,
                  uint32_t first_index = 0) {
    Points points;
    for (uint32_t i = 0; i < (1u << m); ++i) {
        pixel.index = first_index + i;
        points.push_back({sampler.sample(pixel, first_dimension), sampler.sample(pixel, first_dimension + 1)});
    }
    return points;
}

TEST(SobolSampler, FirstPairOfEveryBlockIsAZeroNetInEveryPixel) {
    for (uint64_t seed : {0ull, 12345ull}) {
        const SobolSampler sampler(seed);
        for (const PixelSampleKey& pixel : kPixels) {
            for (uint32_t block : {0u, 1u, 7u}) {
                for (int m : {4, 6}) {
                    EXPECT_EQ(test_support::net_t_value(pixel_pair(sampler, pixel, 4 * block, m)), 0)
                        << "pixel " << pixel.x << "," << pixel.y << " block " << block << " m=" << m;
                }
            }
        }
    }
}

TEST(SobolSampler, SecondPairOfEveryBlockKeepsSobolStratification) {
    // Scrambling and shuffling must preserve the t-value of Sobol' dimensions 2-3 exactly.
    const auto unscrambled_t = [](int m) {
        Points points;
        for (uint32_t i = 0; i < (1u << m); ++i) {
            points.push_back({sobol_sample(i, 2) * 0x1p-32, sobol_sample(i, 3) * 0x1p-32});
        }
        return test_support::net_t_value(points);
    };
    const SobolSampler sampler(99);
    for (const PixelSampleKey& pixel : kPixels) {
        for (uint32_t block : {0u, 3u}) {
            for (int m : {4, 6}) {
                const int t = test_support::net_t_value(pixel_pair(sampler, pixel, 4 * block + 2, m));
                EXPECT_EQ(t, unscrambled_t(m)) << "pixel " << pixel.x << "," << pixel.y << " m=" << m;
                EXPECT_LE(t, 1);
            }
        }
    }
}

TEST(SobolSampler, LaterAlignedBlocksOfSamplesAreStratifiedToo) {
    // Samples 64..127 of a pixel are another aligned block of the shuffled sequence.
    const SobolSampler sampler(5);
    EXPECT_EQ(test_support::net_t_value(pixel_pair(sampler, {3, 3, 0}, 0, 6, 64)), 0);
    EXPECT_EQ(test_support::net_t_value(pixel_pair(sampler, {3, 3, 0}, 4, 4, 16 * 11)), 0);
}

TEST(SobolSampler, EveryDimensionHasOnePointPerInterval) {
    const SobolSampler sampler(8);
    for (const PixelSampleKey& pixel : kPixels) {
        for (uint32_t dimension = 0; dimension < 12; ++dimension) {
            for (int m : {4, 6, 10}) {
                std::vector<int> hits(1u << m, 0);
                PixelSampleKey key = pixel;
                for (key.index = 0; key.index < (1u << m); ++key.index) {
                    ++hits[static_cast<int>(sampler.sample(key, dimension) * (1u << m))];
                }
                for (int count : hits) ASSERT_EQ(count, 1) << "dimension " << dimension << " m=" << m;
            }
        }
    }
}

TEST(SobolSampler, NonPowerOfTwoCountsStayWellSpread) {
    // The first 100 samples extend the first 64 (one per 1/64) and lie within the first 128 (at most one per
    // 1/128), so every interval of length 1/64 holds one or two of them.
    const SobolSampler sampler(11);
    for (uint32_t dimension : {0u, 1u, 2u, 3u, 6u}) {
        std::vector<int> hits(64, 0);
        for (uint32_t i = 0; i < 100; ++i) ++hits[static_cast<int>(sampler.sample({8, 9, i}, dimension) * 64)];
        for (int count : hits) {
            EXPECT_GE(count, 1);
            EXPECT_LE(count, 2);
        }
    }
}

TEST(SobolSampler, PixelsAreDecorrelated) {
    const SobolSampler sampler(21);
    // Different pixels see different points...
    EXPECT_NE(pixel_pair(sampler, {0, 0, 0}, 0, 4), pixel_pair(sampler, {1, 0, 0}, 0, 4));
    EXPECT_NE(pixel_pair(sampler, {0, 0, 0}, 0, 4), pixel_pair(sampler, {0, 1, 0}, 0, 4));
    // ... and blocks within a pixel are shuffled independently, not copies of each other.
    EXPECT_NE(pixel_pair(sampler, {0, 0, 0}, 0, 4), pixel_pair(sampler, {0, 0, 0}, 4, 4));
    // The first sample across a 64x64 tile is uniformly distributed, as independent per-pixel sequences are;
    // an unshuffled or merely translated sequence would give every pixel (nearly) the same first point.
    const test_support::Grid2D grid{0, 1, 0, 1, 16, 16};
    const auto first_point = [&](std::size_t i) {
        const PixelSampleKey key{static_cast<uint32_t>(i % 64), static_cast<uint32_t>(i / 64), 0};
        return test_support::Point2{sampler.sample(key, 0), sampler.sample(key, 1)};
    };
    const auto result = test_support::chi_square_test_2d(grid, 64 * 64, first_point, [](double, double) { return 1.0; });
    EXPECT_GT(result.p_value, 0.01);
}

TEST(SobolSampler, BlocksAreShuffledIndependently) {
    // Without a per-block index shuffle, dimension 4 would be a re-scrambled copy of dimension 0 and the pair
    // (0, 4) would fill only 8 of the 64 cells below. With it, the pair is jointly uniform.
    const SobolSampler sampler(31);
    const test_support::Grid2D grid{0, 1, 0, 1, 8, 8};
    const auto cross_block_point = [&](std::size_t i) {
        const PixelSampleKey key{static_cast<uint32_t>(i / 1024), 3, static_cast<uint32_t>(i % 1024)};
        return test_support::Point2{sampler.sample(key, 0), sampler.sample(key, 4)};
    };
    const auto result =
        test_support::chi_square_test_2d(grid, 16 * 1024, cross_block_point, [](double, double) { return 1.0; });
    EXPECT_GT(result.p_value, 0.01);
}

TEST(SobolSampler, IntegratesSmoothFunctionsFarBetterThanIndependentSampling) {
    // f(x, y) = exp(-(x^2 + y^2)); its integral over the unit square is (sqrt(pi)/2 erf(1))^2.
    const double exact = std::pow(std::sqrt(std::numbers::pi) / 2 * std::erf(1.0), 2);
    const auto rms_error = [&](const Sampler& sampler, uint32_t first_dimension) {
        constexpr uint32_t samples = 1024, pixels = 32;
        double squared_error = 0;
        for (uint32_t p = 0; p < pixels; ++p) {
            double sum = 0;
            for (uint32_t i = 0; i < samples; ++i) {
                const PixelSampleKey key{p, 7 * p, i};
                const double x = sampler.sample(key, first_dimension), y = sampler.sample(key, first_dimension + 1);
                sum += std::exp(-(x * x + y * y));
            }
            squared_error += std::pow(sum / samples - exact, 2);
        }
        return std::sqrt(squared_error / pixels);
    };
    for (uint64_t seed : {1ull, 2ull}) {
        const double independent = rms_error(IndependentSampler(seed), 0);
        for (uint32_t first_dimension : {0u, 2u, 4u}) {
            const double sobol = rms_error(SobolSampler(seed), first_dimension);
            // Independent: ~0.006 (n^-1/2); scrambled Sobol': ~1e-4 or better (about n^-3/2 for smooth f).
            EXPECT_LT(sobol, independent / 20) << "seed " << seed << " dimensions " << first_dimension;
        }
    }
}

}  // namespace
}  // namespace isotrace

namespace isotrace {
namespace {

// The sampler computes its values in the bit-reversed domain with a per-sample context; they must equal the
// definition written out: shuffle the index by nested_uniform_scramble with hash(seed, x, y, block), take the
// Sobol' point of the shuffled index, Owen-scramble each dimension with its own seed.
TEST(SobolSampler, BlocksEqualTheDefinitionOfShuffledOwenScrambledSobol) {
    const SobolSampler sampler(0x5eedull);
    for (const PixelSampleKey& pixel : kPixels) {
        for (uint32_t index : {0u, 1u, 2u, 77u, 65535u, 0x80000001u}) {
            PixelSampleKey key = pixel;
            key.index = index;
            const PixelSampleContext context = sampler.context(key);
            for (uint32_t block : {0u, 1u, 9u, 1000u}) {
                const uint64_t block_hash = hash_combine(uint64_t(0x5eed), key.x, key.y, block);
                const uint32_t shuffled = nested_uniform_scramble(index, static_cast<uint32_t>(block_hash));
                const Sampler::Block values = sampler.sample_block(context, block);
                for (uint32_t d = 0; d < 4; ++d) {
                    const uint32_t seed = mix32(static_cast<uint32_t>(block_hash >> 32) ^ (d + 1) * 0x9e3779b9u);
                    const float expected = uint_to_unit_float(nested_uniform_scramble(sobol_sample(shuffled, d), seed));
                    EXPECT_EQ(values[d], expected) << "index " << index << " block " << block << " dim " << d;
                    EXPECT_EQ(sampler.sample(key, 4 * block + d), expected);
                }
            }
        }
    }
}

// Several samples drawn together (a packet's: one pixel, four at a time and the rest one by one; or of several
// pixels) give what each draws alone.
TEST(SobolSampler, BlocksDrawnTogetherEqualBlocksDrawnAlone) {
    const SobolSampler sampler(0x5eedull);
    for (std::size_t count : {1u, 3u, 4u, 7u, 8u}) {
        for (bool one_pixel : {true, false}) {
            std::vector<PixelSampleContext> contexts;
            for (std::size_t i = 0; i < count; ++i) {
                PixelSampleKey key = one_pixel ? kPixels[0] : kPixels[i % std::size(kPixels)];
                key.index = 13 + std::uint32_t(i) * 977u;
                contexts.push_back(sampler.context(key));
            }
            for (uint32_t block : {0u, 5u, 1000u}) {
                std::vector<Sampler::Block> together(count);
                sampler.sample_blocks(contexts, block, together);
                for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(together[i], sampler.sample_block(contexts[i], block));
            }
        }
    }
}

}  // namespace
}  // namespace isotrace
