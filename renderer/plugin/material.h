#pragma once
// Material: surface appearance. The preview integrator needs albedo and emission; the BSDF interface of the
// path tracer extends this class.
#include "renderer/math/rgb.h"
#include "renderer/plugin/registry.h"

namespace isotrace {

struct SurfaceHit;

class Material {
public:
    virtual ~Material() = default;
    // Directional-hemispherical reflectance for the albedo AOV and diffuse previews.
    virtual Rgb albedo(const SurfaceHit& hit) const = 0;
    // Radiance emitted towards the viewer (zero for non-emitters).
    virtual Rgb emission(const SurfaceHit&) const { return {}; }
};

Registry<Material>& material_registry();

}  // namespace isotrace
