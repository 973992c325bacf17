#pragma once
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "renderer/core/ray.h"
#include "renderer/math/rgb.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/registry.h"
#include "renderer/plugin/surface_hit.h"
#include "renderer/sampling/sampler.h"

namespace isotrace {

class RenderScene;

// What the camera ray saw first, for the AOVs. Integrators fill it from their primary intersection.
struct PrimaryHitRecord {
    bool hit = false;
    Rgb albedo;
    Vec3f shading_normal;
    Vec3f position;
    float depth = 0;
    std::uint32_t object_id = 0;
    std::uint32_t primitive_id = 0;
    // Whether the albedo is wanted (the film keeps it): a textured material evaluates its textures for it.
    bool keeps_albedo = true;

    // Records `hit` (seen first) with its material's albedo there when that is kept, black otherwise.
    void record(const SurfaceHit& hit) {
        record(hit, keeps_albedo && hit.material ? hit.material->albedo(hit) : Rgb());
    }
    // Records `hit` (seen first) with the material's albedo there.
    void record(const SurfaceHit& hit, const Rgb& surface_albedo) {
        this->hit = true;
        albedo = surface_albedo;
        shading_normal = hit.shading_normal;
        position = hit.position;
        object_id = hit.object_index;
        primitive_id = hit.primitive_id;
    }
};

class Integrator {
public:
    virtual ~Integrator() = default;
    // Radiance arriving along `camera_ray` (in the working space).
    virtual Rgb radiance(const Ray& camera_ray, const RenderScene& scene, SampleStream& samples,
                         PrimaryHitRecord& primary) const = 0;
    // How many samples radiance_of_samples() traces together in `scene` (1 to kMaxSamplesTogether): the renderer
    // hands it groups of that size, a pixel's samples and then the next pixel's. 1 by default.
    static constexpr std::size_t kMaxSamplesTogether = 32;
    virtual std::size_t samples_traced_together(const RenderScene& scene) const {
        (void)scene;
        return 1;
    }
    // How such groups are traced, for the render statistics ("" when samples are traced one at a time).
    virtual std::string packet_description(const RenderScene& scene) const {
        (void)scene;
        return "";
    }
    // Several samples at once (a pixel's consecutive sample indices, then the next pixel's): radiance[i] for
    // camera_rays[i] with samples[i] and primary[i]. A sample's result must not depend on its companions. By
    // default, radiance() for each in turn.
    virtual void radiance_of_samples(std::span<const Ray> camera_rays, const RenderScene& scene,
                                     std::span<SampleStream> samples, std::span<PrimaryHitRecord> primary,
                                     std::span<Rgb> radiance) const {
        for (std::size_t i = 0; i < camera_rays.size(); ++i)
            radiance[i] = this->radiance(camera_rays[i], scene, samples[i], primary[i]);
    }
    // Settings worth recording in the image metadata ("isotrace:integrator:<key>").
    virtual std::map<std::string, std::string> settings() const { return {}; }
    // The light of `scene` this integrator leaves out of the image, one phrase each, so that the CLI can warn that
    // the picture is not what the scene describes. Empty (the default) when it renders all of it.
    virtual std::vector<std::string> light_left_out(const RenderScene& scene) const {
        (void)scene;
        return {};
    }
};

Registry<Integrator>& integrator_registry();

}  // namespace isotrace
