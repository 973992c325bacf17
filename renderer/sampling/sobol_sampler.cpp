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

SobolSampler::BlockPoint SobolSampler::block_point(const PixelSampleContext& context, uint32_t block) {
    // One shuffle per block keeps the block's four dimensions a single 4-D Sobol' point; separate blocks
    // are statistically independent (Burley's "padding"). The shuffle is nested_uniform_scramble(index), kept
    // bit-reversed for the reversed Sobol' tables.
    const uint64_t block_hash = hash_extend(context.pixel_hash, block);
    return {block_hash, laine_karras_permutation(context.reversed_index, static_cast<uint32_t>(block_hash))};
}

float SobolSampler::sample(const PixelSampleKey& key, uint32_t dimension) const {
    return sample_block(context(key), dimension / kSobolDimensions)[dimension % kSobolDimensions];
}

// The four dimensions in the four lanes of a vector: the scramble is the same bit arithmetic per lane.
Sampler::Block SobolSampler::sample_block(const PixelSampleContext& context, uint32_t block) const {
    static_assert(kBlockDimensions == kSobolDimensions && kSobolDimensions == 4);
    const BlockPoint point = block_point(context, block);
    const Float4 values = scrambled_block(sobol_point_bit_reversed(point.reversed_shuffled_index),
                                          static_cast<uint32_t>(point.block_hash >> 32));
    return {values[0], values[1], values[2], values[3]};
}

}  // namespace isotrace
