#include "renderer/sampling/sampler.h"

namespace isotrace {

Sampler::Sampler(uint64_t seed) : seed_(seed) {}

Sampler::~Sampler() = default;

SampleStream::SampleStream(const Sampler& sampler, PixelSampleKey key) : sampler_(sampler), key_(key) {}

float SampleStream::value(uint32_t dimension) {
    const uint32_t block = dimension / Sampler::kBlockDimensions;
    if (block != cached_block_) {
        cache_ = sampler_.sample_block(key_, block);
        cached_block_ = block;
    }
    return cache_[dimension % Sampler::kBlockDimensions];
}

float SampleStream::next_1d() { return value(dimension_++); }

std::array<float, 2> SampleStream::next_2d() {
    dimension_ += dimension_ & 1u;
    const std::array<float, 2> pair = {value(dimension_), value(dimension_ + 1)};
    dimension_ += 2;
    return pair;
}

}  // namespace isotrace
