#pragma once
// Sampler: the source of every random number in a render. A value is a pure function of
// (pixel, sample index, dimension, seed), so renders are reproducible regardless of thread scheduling.
#include <array>
#include <cstdint>
#include <span>

namespace isotrace {

struct PixelSampleKey {
    uint32_t x, y, index;
};

// What every dimension of one pixel sample shares, computed once per sample rather than once per block:
// the hash of (seed, x, y) and the sample index with its bits reversed (for the Sobol' sampler's shuffle).
struct PixelSampleContext {
    PixelSampleKey key;
    uint64_t pixel_hash;      // hash_combine(seed, x, y)
    uint32_t reversed_index;  // reverse_bits(key.index)

    // The context of the same pixel's sample `index`, without hashing the pixel again.
    PixelSampleContext of_sample(uint32_t index) const;
};

class Sampler {
public:
    explicit Sampler(uint64_t seed);
    virtual ~Sampler();

    // Value in [0,1) for (pixel, sample index, dimension); a pure function of those and the seed.
    virtual float sample(const PixelSampleKey& key, uint32_t dimension) const = 0;
    // Dimensions 4 * block .. 4 * block + 3 together: equal to four sample() calls, but samplers may share
    // work between them (the Sobol' sampler shuffles the index once per block) and with the other blocks of
    // the same pixel sample (the context).
    static constexpr uint32_t kBlockDimensions = 4;
    using Block = std::array<float, kBlockDimensions>;
    PixelSampleContext context(const PixelSampleKey& key) const;
    virtual Block sample_block(const PixelSampleContext& context, uint32_t block) const {
        Block values;
        for (uint32_t i = 0; i < kBlockDimensions; ++i) values[i] = sample(context.key, block * kBlockDimensions + i);
        return values;
    }

    // sample_block for several samples of one pixel at once (the contexts of one pixel, any indices): values[i] for
    // contexts[i]. Samplers may share work between them (the Sobol' sampler hashes the pixel's block once); by
    // default one block at a time.
    virtual void sample_blocks(std::span<const PixelSampleContext> contexts, uint32_t block,
                               std::span<Block> values) const {
        for (std::size_t i = 0; i < contexts.size(); ++i) values[i] = sample_block(contexts[i], block);
    }

    uint64_t seed() const { return seed_; }

private:
    uint64_t seed_;
};

// Hands out consecutive dimensions for one pixel sample. Values are fetched a block of four dimensions at a
// time and cached; the values themselves depend only on (pixel, index, dimension, seed). The sampler must
// outlive the stream. Default-constructed streams only serve to be assigned (arrays of a packet's streams).
class SampleStream {
public:
    SampleStream() = default;
    SampleStream(const Sampler& sampler, PixelSampleKey key);
    // The stream of the sample `context` names (Sampler::context, PixelSampleContext::of_sample).
    static SampleStream of_context(const Sampler& sampler, const PixelSampleContext& context) {
        SampleStream stream;
        stream.sampler_ = &sampler;
        stream.context_ = context;
        return stream;
    }

    float next_1d() { return value(dimension_++); }
    // Two consecutive dimensions starting at an even dimension: if the counter is odd, one dimension is
    // skipped so the pair lines up with the samplers' stratified pairs (Sobol' dimensions 0-1, 2-3).
    std::array<float, 2> next_2d() {
        dimension_ += dimension_ & 1u;
        const std::array<float, 2> pair = {value(dimension_), value(dimension_ + 1)};
        dimension_ += 2;
        return pair;
    }
    // The four dimensions of the next whole block (skipping to its start), as one Sobol' block: the path tracer
    // takes a bounce's dimensions this way rather than one value at a time.
    Sampler::Block next_block() { return sampler_->sample_block(context_, take_block()); }
    // Moves past the next whole block as next_block() does, without computing it: for dimensions that no one
    // reads this time, so that the dimensions after them keep their numbers.
    void skip_block() { take_block(); }
    // The dimension the next next_1d() call will use.
    uint32_t dimension() const { return dimension_; }

    // Several streams of one pixel and sampler (at most kMaxStreamsTogether) whose counters stand in the same
    // block: fill_caches computes that block for all of them together (Sampler::sample_blocks), so that their next
    // next_1d() and next_2d() calls read it without computing.
    static constexpr std::size_t kMaxStreamsTogether = 32;
    static void fill_caches(std::span<SampleStream> streams);

private:
    // The index of the next whole block (the current one if the counter is at its start), the counter moved past it.
    uint32_t take_block() {
        const uint32_t block = (dimension_ + Sampler::kBlockDimensions - 1) / Sampler::kBlockDimensions;
        dimension_ = (block + 1) * Sampler::kBlockDimensions;
        return block;
    }
    // Inline: several calls per bounce on the path tracer's hottest loop.
    float value(uint32_t dimension) {
        const uint32_t block = dimension / Sampler::kBlockDimensions;
        if (block != cached_block_) {
            cache_ = sampler_->sample_block(context_, block);
            cached_block_ = block;
        }
        return cache_[dimension % Sampler::kBlockDimensions];
    }

    const Sampler* sampler_ = nullptr;
    PixelSampleContext context_{};
    uint32_t dimension_ = 0;
    uint32_t cached_block_ = UINT32_MAX;
    Sampler::Block cache_{};
};

}  // namespace isotrace
