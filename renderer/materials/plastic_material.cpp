// Coated diffuse ("plastic"): a clear dielectric coating, smooth or rough, over a Lambertian base. The coating's
// tables are built once per material.
#include "renderer/bsdf/coated_diffuse_bsdf.h"
#include "renderer/materials/roughness_parameters.h"
#include "renderer/plugin/material.h"
#include "renderer/textures/texture_at_hit.h"
#include "renderer/textures/texture_parser.h"

namespace isotrace {
namespace {

class PlasticMaterial final : public Material {
public:
    PlasticMaterial(ColourTexturePtr reflectance, float ior, float alpha)
        : reflectance_(std::move(reflectance)), coating_(ior, alpha) {}
    Rgb albedo(const SurfaceHit& hit) const override { return texture_at_hit(*reflectance_, hit); }
    SurfaceBsdf bsdf(const SurfaceHit& hit) const override {
        return CoatedDiffuseBsdf(coating_, albedo(hit));
    }
    TextureNeeds texture_needs() const override { return reflectance_->needs(); }

private:
    ColourTexturePtr reflectance_;
    DielectricCoating coating_;
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(material_registry, "plastic",
                         "coated diffuse; reflectance (colour or texture, 0.5), ior (1.5), roughness (0 = smooth), roughness_v (= roughness)",
                         [](const SceneNode& node) -> std::unique_ptr<Material> {
                             ColourTexturePtr reflectance =
                                 parse_colour_texture(node, "reflectance", Rgb(0.5f), ColourRange::Reflectance);
                             const double ior = node.number_or("ior", 1.5, {1.0, 10.0, true, false});
                             const MicrofacetAlphas alphas = parse_roughness(node, 0.0);
                             if (alphas.x != alphas.y) node.fail_at("roughness_v", "plastic coatings are isotropic");
                             return std::make_unique<PlasticMaterial>(std::move(reflectance), float(ior), alphas.x);
                         })

}  // namespace isotrace
