#pragma once
// Unidirectional path tracer with next-event estimation and multiple importance sampling (power heuristic)
// of light sampling and BSDF sampling, Russian roulette after `russian_roulette_depth` bounces, and optional
// clamping of each contribution (off by default; recorded in the image metadata when on).
// With max_depth = 1 it computes direct lighting only (registered as "direct").
#include <map>
#include <string>

#include "renderer/plugin/integrator.h"

namespace isotrace {

struct PathSettings {
    int max_depth = 16;               // bounces; 1 = direct lighting
    int russian_roulette_depth = 4;   // first bounce at which paths may be terminated
    float clamp = 0;                  // > 0: scale any single contribution down to this max channel value
};

class PathIntegrator final : public Integrator {
public:
    explicit PathIntegrator(const PathSettings& settings) : settings_(settings) {}
    Rgb radiance(const Ray& camera_ray, const RenderScene& scene, SampleStream& samples,
                 PrimaryHitRecord& primary) const override;
    std::map<std::string, std::string> settings() const override;

private:
    PathSettings settings_;
};

}  // namespace isotrace
