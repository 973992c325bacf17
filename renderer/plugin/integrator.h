#pragma once
#include <cstdint>
#include <map>
#include <string>

#include "renderer/core/ray.h"
#include "renderer/math/rgb.h"
#include "renderer/plugin/registry.h"
#include "renderer/scene/surface_hit.h"

namespace isotrace {

class RenderScene;
class SampleStream;

// What the camera ray saw first, for the AOVs. Integrators fill it from their primary intersection.
struct PrimaryHitRecord {
    bool hit = false;
    Rgb albedo;
    Vec3f shading_normal;
    Vec3f position;
    float depth = 0;
    std::uint32_t object_id = 0;
    std::uint32_t primitive_id = 0;

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
    // Settings worth recording in the image metadata ("isotrace:integrator:<key>").
    virtual std::map<std::string, std::string> settings() const { return {}; }
};

Registry<Integrator>& integrator_registry();

}  // namespace isotrace
