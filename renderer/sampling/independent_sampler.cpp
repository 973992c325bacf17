#include "renderer/sampling/independent_sampler.h"

#include "renderer/sampling/hash.h"

namespace isotrace {

namespace {

float value_of(uint64_t pixel_hash, uint32_t index, uint32_t dimension) {
    return uint_to_unit_float(static_cast<uint32_t>(hash_extend(pixel_hash, index, dimension) >> 32));
}

}  // namespace

float IndependentSampler::sample(const PixelSampleKey& key, uint32_t dimension) const {
    return value_of(hash_combine(seed(), key.x, key.y), key.index, dimension);
}

Sampler::Block IndependentSampler::sample_block(const PixelSampleContext& context, uint32_t block) const {
    Block values;
    for (uint32_t i = 0; i < kBlockDimensions; ++i)
        values[i] = value_of(context.pixel_hash, context.key.index, block * kBlockDimensions + i);
    return values;
}

}  // namespace isotrace
