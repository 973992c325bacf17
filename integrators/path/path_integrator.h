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
    // On flat Lambertian scenes (RenderScene::flat_lambertian()) eight samples are traced together, paths in SIMD
    // lanes (flat_lambertian_packets.h), with radiance()'s results; elsewhere one at a time.
    std::size_t samples_traced_together(const RenderScene& scene) const override;
    std::string packet_description(const RenderScene& scene) const override;
    void radiance_of_samples(std::span<const Ray> camera_rays, const RenderScene& scene, std::span<SampleStream> samples,
                             std::span<PrimaryHitRecord> primary, std::span<Rgb> radiance) const override;
    std::map<std::string, std::string> settings() const override;

private:
    PathSettings settings_;
};

}  // namespace isotrace
