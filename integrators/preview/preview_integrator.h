#pragma once
// Preview integrator: one bounce of light, enough to judge shape and placement before the path tracer.
//   L = Le + albedo * (sum over lights of E_light * cos / pi * visibility  +  ambient * occlusion)
// Ambient occlusion uses cosine-weighted rays, so `ambient * visibility` is an unbiased estimate of the
// diffuse light from a uniform sky of radiance `ambient` (clipped to ambient_distance when set).
#include "renderer/plugin/integrator.h"

namespace isotrace {

struct PreviewSettings {
    Rgb ambient{0.2f, 0.2f, 0.2f};
    Rgb background{0.2f, 0.2f, 0.2f};
    int ambient_samples = 1;
    float ambient_distance = 1e30f;
};

class PreviewIntegrator final : public Integrator {
public:
    explicit PreviewIntegrator(const PreviewSettings& settings) : settings_(settings) {}
    Rgb radiance(const Ray& camera_ray, const RenderScene& scene, SampleStream& samples,
                 PrimaryHitRecord& primary) const override;
    // An environment shows only as light (rays leaving the scene see the uniform background), and emissive objects
    // that are not sampled as area lights light nothing else: the preview finds light only by sampling lights.
    std::vector<std::string> light_left_out(const RenderScene& scene) const override;

private:
    PreviewSettings settings_;
};

}  // namespace isotrace
