#pragma once
// SobolSampler: shuffled, Owen-scrambled Sobol' points after Burley 2020 ("Practical Hash-based Owen
// Scrambling"). Dimensions are taken in blocks of kSobolDimensions (4); block b of a pixel uses Sobol'
// dimensions 0-3 with the sample index shuffled by a nested uniform scramble seeded by hash(pixel, seed, b),
// and each value Owen-scrambled with its own hash. Shuffling maps the first 2^m indices onto an aligned
// block of 2^m Sobol' indices, so every pixel gets its own, decorrelated, but equally stratified points:
//   - each dimension: one point per interval of length 2^-m among the first 2^m samples;
//   - dimensions (4b, 4b+1): a (0,m,2)-net, i.e. one point in every elementary interval of area 2^-m;
//   - dimensions (4b+2, 4b+3): the t-value of Sobol' dimensions 2-3 (t <= 2, and t = 1 from m = 5 on):
//     no Sobol' pair other than 0-1 is a (0,2)-sequence, so this pair is slightly less stratified.
// Any sample count works; powers of two stratify best. No state, no precomputed per-pixel tables.
#include "renderer/sampling/sampler.h"

namespace isotrace {

class SobolSampler final : public Sampler {
public:
    using Sampler::Sampler;

    float sample(const PixelSampleKey& key, uint32_t dimension) const override;
    Block sample_block(const PixelSampleContext& context, uint32_t block) const override;
    void sample_blocks(std::span<const PixelSampleContext> contexts, uint32_t block,
                       std::span<Block> values) const override;

private:
    static Block block_values(uint64_t block_hash, uint32_t reversed_index);
};

}  // namespace isotrace
