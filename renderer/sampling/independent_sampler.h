#pragma once
// IndependentSampler: every value is an independent uniform hash. The reference against which
// stratified samplers are judged, and the right choice when a test needs truly independent samples.
#include "renderer/sampling/sampler.h"

namespace isotrace {

class IndependentSampler final : public Sampler {
public:
    using Sampler::Sampler;

    float sample(const PixelSampleKey& key, uint32_t dimension) const override;
    Block sample_block(const PixelSampleContext& context, uint32_t block) const override;
};

}  // namespace isotrace
