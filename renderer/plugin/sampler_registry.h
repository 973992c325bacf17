#pragma once
#include <cstdint>

#include "renderer/plugin/registry.h"
#include "renderer/sampling/sampler.h"

namespace isotrace {

// Samplers are created with the seed chosen by the scene or the command line.
Registry<Sampler, std::uint64_t>& sampler_registry();

}  // namespace isotrace
