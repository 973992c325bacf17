#pragma once
// The first dimensions of the 32-bit Sobol' sequence with Joe & Kuo's direction numbers
// (new-joe-kuo-6.21201), evaluated by random access in natural (not Gray-code) order.
#include <cstdint>

#include "renderer/math/lanes4.h"

namespace isotrace {

inline constexpr uint32_t kSobolDimensions = 4;

// Sobol' value of `index` in `dimension` (< kSobolDimensions) as 0.32 fixed point (divide by 2^32 for [0,1)).
uint32_t sobol_sample(uint32_t index, uint32_t dimension);

// The same with index and value bit-reversed: reverse_bits(sobol_sample(reverse_bits(reversed_index), d)).
// Owen scrambling and the index shuffle both work on reversed bits, so the sampler needs no reversal here.
uint32_t sobol_sample_bit_reversed(uint32_t reversed_index, uint32_t dimension);

// All kSobolDimensions dimensions of sobol_sample_bit_reversed at once, one per lane.
Uint4 sobol_point_bit_reversed(uint32_t reversed_index);

}  // namespace isotrace
