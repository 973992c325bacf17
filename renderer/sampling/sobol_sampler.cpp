#include "renderer/sampling/sobol_sampler.h"

#include "renderer/sampling/hash.h"
#include "renderer/sampling/owen_scramble.h"
#include "renderer/sampling/sobol.h"

namespace isotrace {

SobolSampler::BlockPoint SobolSampler::block_point(const PixelSampleContext& context, uint32_t block) {
    // One shuffle per block keeps the block's four dimensions a single 4-D Sobol' point; separate blocks
    // are statistically independent (Burley's "padding"). The shuffle is nested_uniform_scramble(index), kept
    // bit-reversed for the reversed Sobol' tables.
    const uint64_t block_hash = hash_extend(context.pixel_hash, block);
    return {block_hash, laine_karras_permutation(context.reversed_index, static_cast<uint32_t>(block_hash))};
}

float SobolSampler::scrambled_value(const BlockPoint& point, uint32_t sobol_dimension) {
    // The four dimensions of a block need independent scrambles, not strong hashing of a fresh key: one 32-bit
    // finaliser round over the block hash and the dimension is enough and costs a fraction of hash_combine.
    const uint32_t scramble_seed =
        mix32(static_cast<uint32_t>(point.block_hash >> 32) ^ (sobol_dimension + 1) * 0x9e3779b9u);
    return uint_to_unit_float(nested_uniform_scramble_of_reversed(
        sobol_sample_bit_reversed(point.reversed_shuffled_index, sobol_dimension), scramble_seed));
}

float SobolSampler::sample(const PixelSampleKey& key, uint32_t dimension) const {
    return scrambled_value(block_point(context(key), dimension / kSobolDimensions), dimension % kSobolDimensions);
}

Sampler::Block SobolSampler::sample_block(const PixelSampleContext& context, uint32_t block) const {
    static_assert(kBlockDimensions == kSobolDimensions);
    const BlockPoint point = block_point(context, block);
    Block values;
    for (uint32_t d = 0; d < kSobolDimensions; ++d) values[d] = scrambled_value(point, d);
    return values;
}

}  // namespace isotrace
