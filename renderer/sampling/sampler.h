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
    // Dimensions (dimension, dimension + 1) together; equal to two sample() calls, but samplers may share
    // work between the two (dimension is even).
    virtual std::array<float, 2> sample_2d(const PixelSampleKey& key, uint32_t dimension) const {
        return {sample(key, dimension), sample(key, dimension + 1)};
    }

    uint64_t seed() const { return seed_; }

private:
    uint64_t seed_;
};

// Hands out consecutive dimensions for one pixel sample; the dimension counter is its only state.
// The sampler must outlive the stream.
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
    const Sampler& sampler_;
    PixelSampleKey key_;
    uint32_t dimension_ = 0;
};

}  // namespace isotrace
