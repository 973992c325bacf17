#include "renderer/sampling/sampler.h"

#include "renderer/sampling/hash.h"
#include "renderer/sampling/owen_scramble.h"

namespace isotrace {

Sampler::Sampler(uint64_t seed) : seed_(seed) {}

Sampler::~Sampler() = default;

PixelSampleContext Sampler::context(const PixelSampleKey& key) const {
    return {key, hash_combine(seed_, key.x, key.y), reverse_bits(key.index)};
}

PixelSampleContext PixelSampleContext::of_sample(uint32_t index) const {
    return {{key.x, key.y, index}, pixel_hash, reverse_bits(index)};
}

SampleStream::SampleStream(const Sampler& sampler, PixelSampleKey key)
    : SampleStream(of_context(sampler, sampler.context(key))) {}

void SampleStream::fill_caches(std::span<SampleStream> streams) {
    std::array<PixelSampleContext, kMaxStreamsTogether> contexts;
    std::array<Sampler::Block, kMaxStreamsTogether> computed;
    if (streams.empty()) return;
    const uint32_t block = streams[0].dimension_ / Sampler::kBlockDimensions;
    for (std::size_t i = 0; i < streams.size(); ++i) contexts[i] = streams[i].context_;
    streams[0].sampler_->sample_blocks(std::span(contexts.data(), streams.size()), block,
                                       std::span(computed.data(), streams.size()));
    for (std::size_t i = 0; i < streams.size(); ++i) {
        streams[i].cache_ = computed[i];
        streams[i].cached_block_ = block;
    }
}

}  // namespace isotrace
