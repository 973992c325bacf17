// Registers the samplers of renderer/sampling (which stays free of scene-format code).
#include "renderer/plugin/sampler_registry.h"
#include "renderer/sampling/independent_sampler.h"
#include "renderer/sampling/sobol_sampler.h"

namespace isotrace {

ISOTRACE_REGISTER_PLUGIN(sampler_registry, "sobol", "Owen-scrambled Sobol' (Burley 2020), best with 2^k spp; seed",
                         [](const SceneNode&, std::uint64_t seed) -> std::unique_ptr<Sampler> {
                             return std::make_unique<SobolSampler>(seed);
                         })

ISOTRACE_REGISTER_PLUGIN(sampler_registry, "independent", "independent uniform random numbers (hashed); seed",
                         [](const SceneNode&, std::uint64_t seed) -> std::unique_ptr<Sampler> {
                             return std::make_unique<IndependentSampler>(seed);
                         })

}  // namespace isotrace
