#include "renderer/sampling/sampler.h"

#include "renderer/sampling/hash.h"
#include "renderer/sampling/owen_scramble.h"

namespace isotrace {

Sampler::Sampler(uint64_t seed) : seed_(seed) {}

Sampler::~Sampler() = default;

PixelSampleContext Sampler::context(const PixelSampleKey& key) const {
    return {key, hash_combine(seed_, key.x, key.y), reverse_bits(key.index)};
}

SampleStream::SampleStream(const Sampler& sampler, PixelSampleKey key)
    : sampler_(&sampler), context_(sampler.context(key)) {}

}  // namespace isotrace
