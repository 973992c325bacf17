#include "renderer/sampling/sobol_sampler.h"

#include "renderer/sampling/hash.h"
#include "renderer/sampling/owen_scramble.h"
#include "renderer/sampling/sobol.h"

namespace isotrace {
namespace {

// Per-dimension Owen scramble seeds of a block: the four dimensions need independent scrambles, not strong
// hashing of a fresh key: one 32-bit finaliser round over the block hash and the dimension is enough and costs
// a fraction of hash_combine.
constexpr uint32_t kSeedStep = 0x9e3779b9u;
constexpr Uint4 kDimensionSalt = {1 * kSeedStep, 2 * kSeedStep, 3 * kSeedStep, 4 * kSeedStep};

// The scramble of a block's four Sobol' values, one per lane, to floats in [0, 1). The library targets baseline
// x86-64, whose SSE2 has no 32-bit lane multiply (each of the six here is emulated in about six instructions); the
// AVX2 clone, chosen once at load time on CPUs that have it, multiplies in one. Integer arithmetic and an exact
// conversion: both clones give the same bits.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
// Not in sanitizer builds: the clones' resolver runs while the library is relocated, before the sanitizer runtime
// is set up, and its instrumented code crashed every ThreadSanitizer test binary at load.
#define ISOTRACE_AVX2_CLONE
#else
#define ISOTRACE_AVX2_CLONE [[gnu::target_clones("avx2", "default")]]
#endif
ISOTRACE_AVX2_CLONE Float4 scrambled_block(Uint4 reversed_sobol, uint32_t block_seed) {
    const Uint4 seeds = mix32(block_seed ^ kDimensionSalt);
    const Uint4 scrambled = nested_uniform_scramble_of_reversed(reversed_sobol, seeds);
    // uint_to_unit_float per lane: the top 24 bits, exact in float.
    return __builtin_convertvector(Int4(scrambled >> 8), Float4) * 0x1p-24f;
}

}  // namespace

// Block `block_hash`'s four values for the sample whose reversed index is `reversed_index`. One shuffle per block
// keeps the block's four dimensions a single 4-D Sobol' point; separate blocks are statistically independent
// (Burley's "padding"). The shuffle is nested_uniform_scramble(index), kept bit-reversed for the reversed Sobol'
// tables.
Sampler::Block SobolSampler::block_values(uint64_t block_hash, uint32_t reversed_index) {
    const uint32_t shuffled = laine_karras_permutation(reversed_index, static_cast<uint32_t>(block_hash));
    const Float4 values = scrambled_block(sobol_point_bit_reversed(shuffled), static_cast<uint32_t>(block_hash >> 32));
    return {values[0], values[1], values[2], values[3]};
}

float SobolSampler::sample(const PixelSampleKey& key, uint32_t dimension) const {
    return sample_block(context(key), dimension / kSobolDimensions)[dimension % kSobolDimensions];
}

// The four dimensions in the four lanes of a vector: the scramble is the same bit arithmetic per lane.
Sampler::Block SobolSampler::sample_block(const PixelSampleContext& context, uint32_t block) const {
    static_assert(kBlockDimensions == kSobolDimensions && kSobolDimensions == 4);
    return block_values(hash_extend(context.pixel_hash, block), context.reversed_index);
}

// The samples of one pixel share the block's hash: computed once for all of them.
void SobolSampler::sample_blocks(std::span<const PixelSampleContext> contexts, uint32_t block,
                                 std::span<Block> values) const {
    if (contexts.empty()) return;
    const uint64_t block_hash = hash_extend(contexts[0].pixel_hash, block);
    for (std::size_t i = 0; i < contexts.size(); ++i)
        values[i] = contexts[i].pixel_hash == contexts[0].pixel_hash
                        ? block_values(block_hash, contexts[i].reversed_index)
                        : sample_block(contexts[i], block);  // not one pixel after all
}

}  // namespace isotrace
