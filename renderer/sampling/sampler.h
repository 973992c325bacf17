#pragma once
// Sampler: the source of every random number in a render. A value is a pure function of
// (pixel, sample index, dimension, seed), so renders are reproducible regardless of thread scheduling.
#include <array>
#include <cstdint>

namespace isotrace {

struct PixelSampleKey {
    uint32_t x, y, index;
};

class Sampler {
public:
    explicit Sampler(uint64_t seed);
    virtual ~Sampler();

    // Value in [0,1) for (pixel, sample index, dimension); a pure function of those and the seed.
    virtual float sample(const PixelSampleKey& key, uint32_t dimension) const = 0;
    // Dimensions 4 * block .. 4 * block + 3 together: equal to four sample() calls, but samplers may share
    // work between them (the Sobol' sampler shuffles the index once per block).
    static constexpr uint32_t kBlockDimensions = 4;
    using Block = std::array<float, kBlockDimensions>;
    virtual Block sample_block(const PixelSampleKey& key, uint32_t block) const {
        Block values;
        for (uint32_t i = 0; i < kBlockDimensions; ++i) values[i] = sample(key, block * kBlockDimensions + i);
        return values;
    }

    uint64_t seed() const { return seed_; }

private:
    uint64_t seed_;
};

// Hands out consecutive dimensions for one pixel sample. Values are fetched a block of four dimensions at a
// time and cached; the values themselves depend only on (pixel, index, dimension, seed). The sampler must
// outlive the stream.
class SampleStream {
public:
    SampleStream(const Sampler& sampler, PixelSampleKey key);

    float next_1d();
    // Two consecutive dimensions starting at an even dimension: if the counter is odd, one dimension is
    // skipped so the pair lines up with the samplers' stratified pairs (Sobol' dimensions 0-1, 2-3).
    std::array<float, 2> next_2d();
    // The dimension the next next_1d() call will use.
    uint32_t dimension() const { return dimension_; }

private:
    float value(uint32_t dimension);

    const Sampler& sampler_;
    PixelSampleKey key_;
    uint32_t dimension_ = 0;
    uint32_t cached_block_ = UINT32_MAX;
    Sampler::Block cache_{};
};

}  // namespace isotrace
