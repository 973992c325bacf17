#include "renderer/sampling/sobol_sampler.h"

#include "renderer/sampling/hash.h"
#include "renderer/sampling/owen_scramble.h"
#include "renderer/sampling/sobol.h"

namespace isotrace {

float SobolSampler::sample(const PixelSampleKey& key, uint32_t dimension) const {
    const uint32_t block = dimension / kSobolDimensions;
    const uint32_t sobol_dimension = dimension % kSobolDimensions;
    // One shuffle per block keeps the block's four dimensions a single 4-D Sobol' point; separate blocks
    // are statistically independent (Burley's "padding").
    const uint64_t block_hash = hash_combine(seed(), key.x, key.y, block);
    const uint32_t shuffled_index = nested_uniform_scramble(key.index, static_cast<uint32_t>(block_hash));
    const uint32_t scramble_seed = static_cast<uint32_t>(hash_combine(block_hash, sobol_dimension));
    return uint_to_unit_float(nested_uniform_scramble(sobol_sample(shuffled_index, sobol_dimension), scramble_seed));
}

}  // namespace isotrace
