#pragma once
// Unidirectional path tracer with next-event estimation and multiple importance sampling (power heuristic)
// of light sampling and BSDF sampling, Russian roulette after `russian_roulette_depth` bounces, and optional
// clamping of each contribution (off by default; recorded in the image metadata when on).
// With max_depth = 1 it computes direct lighting only (registered as "direct").
#include <map>
#include <optional>
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
    // Up to kMaxSamplesTogether samples (a pixel's, or several pixels') are traced together, with radiance()'s
    // results: as paths in step whose rays are packet queries.
    std::size_t samples_traced_together(const RenderScene& scene) const override;
    std::string packet_description(const RenderScene& scene) const override;
    void radiance_of_samples(std::span<const Ray> camera_rays, const RenderScene& scene, std::span<SampleStream> samples,
                             std::span<PrimaryHitRecord> primary, std::span<Rgb> radiance) const override;
    std::map<std::string, std::string> settings() const override;

private:
    struct Path;
    PathSettings settings_;

    // One bounce of `path` at what its ray `ray` found: gathers emission there (or escaped light), sets `shadow` to
    // the shadow ray of next-event estimation when Path::casts_shadow (and leaves it alone otherwise), and samples the
    // next ray into `ray`; false when the path ends there.
    bool bounce(Path& path, Ray& ray, Ray& shadow, const std::optional<SurfaceHit>& found, const RenderScene& scene,
                SampleStream& samples, PrimaryHitRecord& primary) const;
    // Adds what the bounce's shadow ray brings, once the caller found it unblocked.
    void add_unblocked(Path& path) const;
};

}  // namespace isotrace
