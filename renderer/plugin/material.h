#pragma once
#include <optional>

// Material: surface appearance. At a hit it provides the BSDF (by value), the albedo for the AOV and previews,
// and emitted radiance.
#include "renderer/bsdf/surface_bsdf.h"
#include "renderer/math/rgb.h"
#include "renderer/math/vec3.h"
#include "renderer/plugin/registry.h"
#include "renderer/plugin/texture.h"

namespace isotrace {

struct SurfaceHit;

class Material {
public:
    virtual ~Material() = default;
    // Bump and normal maps: replaces hit.shading_normal (and, for anisotropic models, sets hit.tangent) before
    // anything else is asked about the hit. The scene calls it on every hit it reports.
    virtual void perturb_normal(SurfaceHit& hit) const { (void)hit; }
    // Directional-hemispherical reflectance, for the albedo AOV and diffuse previews.
    virtual Rgb albedo(const SurfaceHit& hit) const = 0;
    // Radiance emitted from `hit` towards `towards_viewer` (unit, pointing away from the surface).
    virtual Rgb emission(const SurfaceHit& hit, const Vec3f& towards_viewer) const {
        (void)hit, (void)towards_viewer;
        return {};
    }
    virtual bool is_emissive() const { return false; }
    // The scattering function at `hit`; empty when the surface absorbs everything (pure emitters).
    virtual SurfaceBsdf bsdf(const SurfaceHit& hit) const {
        (void)hit;
        return {};
    }
    // Materials that can blend with others where a surface's parts meet (blob elements with materials of their
    // own) describe themselves at a hit as principled parameters; the blend mixes those.
    virtual bool can_blend() const { return false; }
    virtual PrincipledParameters principled_parameters(const SurfaceHit& hit) const {
        (void)hit;
        return {};
    }
    // What the material's textures need from the surfaces it is put on (uv, a field), checked by the loader.
    virtual TextureNeeds texture_needs() const { return {}; }
};

Registry<Material>& material_registry();

}  // namespace isotrace
