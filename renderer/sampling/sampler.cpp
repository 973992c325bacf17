#include "renderer/sampling/sampler.h"

namespace isotrace {

Sampler::Sampler(uint64_t seed) : seed_(seed) {}

Sampler::~Sampler() = default;

SampleStream::SampleStream(const Sampler& sampler, PixelSampleKey key) : sampler_(sampler), key_(key) {}

float SampleStream::next_1d() {
    return sampler_.sample(key_, dimension_++);
}

std::array<float, 2> SampleStream::next_2d() {
    dimension_ += dimension_ & 1u;
    const std::array<float, 2> pair = sampler_.sample_2d(key_, dimension_);
    dimension_ += 2;
    return pair;
}

}  // namespace isotrace
