#include "renderer/sampling/sampler.h"

#include <gtest/gtest.h>

#include "renderer/sampling/independent_sampler.h"
#include "renderer/sampling/sobol_sampler.h"

namespace isotrace {
namespace {

// Encodes the requested dimension in the value so the tests can see which dimensions a stream asked for.
class DimensionEchoSampler final : public Sampler {
public:
    DimensionEchoSampler() : Sampler(0) {}
    float sample(const PixelSampleKey&, uint32_t dimension) const override { return dimension / 1024.0f; }
};

TEST(SampleStream, HandsOutConsecutiveDimensions) {
    const DimensionEchoSampler sampler;
    SampleStream stream(sampler, {3, 4, 5});
    EXPECT_EQ(stream.dimension(), 0u);
    EXPECT_EQ(stream.next_1d(), 0 / 1024.0f);
    EXPECT_EQ(stream.next_1d(), 1 / 1024.0f);
    const auto pair = stream.next_2d();
    EXPECT_EQ(pair[0], 2 / 1024.0f);
    EXPECT_EQ(pair[1], 3 / 1024.0f);
    EXPECT_EQ(stream.dimension(), 4u);
}

TEST(PixelSampleContext, AnotherSampleOfThePixelIsThatSamplesOwnContext) {
    const SobolSampler sampler(7);
    const PixelSampleContext pixel = sampler.context({12, 34, 5});
    for (uint32_t index : {0u, 1u, 5u, 6u, 31u, 1000u, 0xffffffffu}) {
        const PixelSampleContext shared = pixel.of_sample(index), own = sampler.context({12, 34, index});
        EXPECT_EQ(shared.key.x, own.key.x);
        EXPECT_EQ(shared.key.y, own.key.y);
        EXPECT_EQ(shared.key.index, own.key.index);
        EXPECT_EQ(shared.pixel_hash, own.pixel_hash);
        EXPECT_EQ(shared.reversed_index, own.reversed_index) << index;
        SampleStream from_shared = SampleStream::of_context(sampler, shared), from_key(sampler, own.key);
        for (int i = 0; i < 12; ++i) EXPECT_EQ(from_shared.next_1d(), from_key.next_1d()) << index << " " << i;
    }
}

TEST(SampleStream, PairsStartOnEvenDimensions) {
    const DimensionEchoSampler sampler;
    SampleStream stream(sampler, {0, 0, 0});
    stream.next_1d();
    const auto pair = stream.next_2d();  // dimension 1 is skipped so the pair is (2, 3)
    EXPECT_EQ(pair[0], 2 / 1024.0f);
    EXPECT_EQ(pair[1], 3 / 1024.0f);
    EXPECT_EQ(stream.dimension(), 4u);
}

TEST(SampleStream, BlocksStartOnMultiplesOfFour) {
    const DimensionEchoSampler sampler;
    SampleStream stream(sampler, {0, 0, 0});
    const Sampler::Block first = stream.next_block();  // at a block start: dimensions 0-3
    EXPECT_EQ(first[0], 0 / 1024.0f);
    EXPECT_EQ(first[3], 3 / 1024.0f);
    stream.next_1d();                                    // dimension 4; 5-7 are skipped
    const Sampler::Block second = stream.next_block();
    EXPECT_EQ(second[0], 8 / 1024.0f);
    EXPECT_EQ(second[3], 11 / 1024.0f);
    EXPECT_EQ(stream.dimension(), 12u);
    EXPECT_EQ(stream.next_1d(), 12 / 1024.0f);
}

TEST(SampleStream, SkippingABlockKeepsTheDimensionsThatFollow) {
    const DimensionEchoSampler sampler;
    SampleStream skipping(sampler, {0, 0, 0}), reading(sampler, {0, 0, 0});
    skipping.next_1d();
    reading.next_1d();
    skipping.skip_block();  // dimensions 4-7, as next_block() would give them
    reading.next_block();
    EXPECT_EQ(skipping.dimension(), reading.dimension());
    EXPECT_EQ(skipping.next_block(), reading.next_block());
}

// Properties every sampler must have, checked for each concrete sampler.
template <class ConcreteSampler>
class EverySampler : public ::testing::Test {};
using ConcreteSamplers = ::testing::Types<IndependentSampler, SobolSampler>;
TYPED_TEST_SUITE(EverySampler, ConcreteSamplers);

// Streams fetch blocks through the per-sample context: the values must be those of sample().
TYPED_TEST(EverySampler, StreamsMatchDirectSampleCalls) {
    const TypeParam sampler(7);
    for (const PixelSampleKey key : {PixelSampleKey{10, 20, 30}, PixelSampleKey{0xffffffffu, 0, 0xfffffffeu}}) {
        SampleStream stream(sampler, key);
        EXPECT_EQ(stream.next_1d(), sampler.sample(key, 0));
        const auto pair = stream.next_2d();
        EXPECT_EQ(pair[0], sampler.sample(key, 2));
        EXPECT_EQ(pair[1], sampler.sample(key, 3));
        for (uint32_t d = 4; d < 40; ++d) EXPECT_EQ(stream.next_1d(), sampler.sample(key, d)) << d;
        const Sampler::Block block = stream.next_block();
        for (uint32_t i = 0; i < Sampler::kBlockDimensions; ++i) EXPECT_EQ(block[i], sampler.sample(key, 40 + i)) << i;
    }
}

TYPED_TEST(EverySampler, IsAPureFunctionOfItsInputs) {
    const TypeParam a(42), b(42);
    for (uint32_t i = 0; i < 64; ++i) {
        const PixelSampleKey key{i % 7, i / 7, i * 13};
        for (uint32_t d = 0; d < 12; ++d) {
            const float first = a.sample(key, d);
            EXPECT_EQ(first, a.sample(key, d));
            EXPECT_EQ(first, b.sample(key, d));
        }
    }
    // Evaluation order does not matter: no hidden state.
    const PixelSampleKey key{5, 6, 7};
    const float before = a.sample(key, 3);
    for (uint32_t d = 0; d < 100; ++d) a.sample({1, 2, d}, d);
    EXPECT_EQ(a.sample(key, 3), before);
    EXPECT_EQ(a.seed(), 42u);
}

TYPED_TEST(EverySampler, DifferentSeedsGiveDifferentValues) {
    const TypeParam a(1), b(2);
    int equal = 0;
    for (uint32_t i = 0; i < 256; ++i) {
        for (uint32_t d = 0; d < 8; ++d) equal += a.sample({i, 3, i % 16}, d) == b.sample({i, 3, i % 16}, d);
    }
    EXPECT_LE(equal, 2);  // 2048 values on a 2^-24 grid: coincidences are vanishingly rare
}

TYPED_TEST(EverySampler, ValuesAreInHalfOpenUnitInterval) {
    const TypeParam sampler(0xfeedfaceull);
    for (uint32_t x : {0u, 1u, 4095u, 0xffffffffu}) {
        for (uint32_t index : {0u, 1u, 255u, 256u, 0xffffffffu}) {
            for (uint32_t d : {0u, 1u, 2u, 3u, 4u, 31u, 1000u, 0xffffffffu}) {
                const float v = sampler.sample({x, 7, index}, d);
                EXPECT_GE(v, 0.0f);
                EXPECT_LT(v, 1.0f);
            }
        }
    }
}

}  // namespace
}  // namespace isotrace
