#include "renderer/sampling/independent_sampler.h"

#include "renderer/sampling/hash.h"

namespace isotrace {

float IndependentSampler::sample(const PixelSampleKey& key, uint32_t dimension) const {
    const uint64_t h = hash_combine(seed(), key.x, key.y, key.index, dimension);
    return uint_to_unit_float(static_cast<uint32_t>(h >> 32));
}

}  // namespace isotrace
