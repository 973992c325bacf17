// Lambertian reflector, optionally also emitting (a glowing diffuse surface). The reflectance may be a texture.

#include "renderer/bsdf/lambert_bsdf.h"
#include "renderer/materials/emission_profile.h"
#include "renderer/plugin/material.h"
#include "renderer/textures/texture_at_hit.h"
#include "renderer/textures/texture_parser.h"

namespace isotrace {
namespace {

class DiffuseMaterial final : public Material {
public:
    DiffuseMaterial(ColourTexturePtr reflectance, const EmissionProfile& emission)
        : reflectance_(std::move(reflectance)), emission_(emission) {}

    Rgb albedo(const SurfaceHit& hit) const override { return texture_at_hit(*reflectance_, hit); }
    Rgb emission(const SurfaceHit& hit, const Vec3f& towards_viewer) const override {
        return emission_.towards(hit, towards_viewer);
    }
    bool is_emissive() const override { return emission_.emits(); }
    SurfaceBsdf bsdf(const SurfaceHit& hit) const override {
        return LambertBsdf(albedo(hit));
    }
    // As principled parameters: a Lambertian base without the specular layer.
    bool can_blend() const override { return true; }
    PrincipledParameters principled_parameters(const SurfaceHit& hit) const override {
        PrincipledParameters lambertian;
        lambertian.base_colour = albedo(hit);
        lambertian.specular = 0;
        return lambertian;
    }
    TextureNeeds texture_needs() const override { return reflectance_->needs(); }

private:
    ColourTexturePtr reflectance_;
    EmissionProfile emission_;
};

std::unique_ptr<Material> create(const SceneNode& node) {
    ColourTexturePtr reflectance = parse_colour_texture(node, "reflectance", Rgb(0.5f), ColourRange::Reflectance);
    return std::make_unique<DiffuseMaterial>(std::move(reflectance),
                                             parse_emission(node, "emission", false, "two_sided_emission"));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(material_registry, "diffuse",
                         "Lambertian; reflectance (colour or texture, docs/textures.md; 0.5), emission (colour, 0), two_sided_emission", create)

}  // namespace isotrace
