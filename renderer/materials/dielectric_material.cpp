// Glass-like dielectric: smooth (delta reflection and refraction) or rough GGX (Walter et al. 2007), with
// interior index of refraction "ior" (exterior: vacuum) and an optional transmission tint.
#include "renderer/bsdf/dielectric_bsdf.h"
#include "renderer/materials/roughness_parameters.h"
#include "renderer/plugin/material.h"

namespace isotrace {
namespace {

class DielectricMaterial final : public Material {
public:
    DielectricMaterial(float ior, MicrofacetAlphas alphas, const Rgb& tint) : ior_(ior), alphas_(alphas), tint_(tint) {}
    Rgb albedo(const SurfaceHit&) const override { return tint_; }
    SurfaceBsdf bsdf(const SurfaceHit&) const override {
        return DielectricBsdf(ior_, alphas_.x, alphas_.y, tint_);
    }

private:
    float ior_;
    MicrofacetAlphas alphas_;
    Rgb tint_;
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(material_registry, "dielectric",
                         "glass; ior (1.5), roughness (0 = smooth), roughness_v, tint (transmission colour, 1)",
                         [](const SceneNode& node) -> std::unique_ptr<Material> {
                             const double ior = node.number_or("ior", 1.5, {1.0, 10.0, true, false});
                             const Rgb tint = node.colour_or("tint", Rgb(1.0f));
                             if (tint.r < 0 || tint.g < 0 || tint.b < 0 || tint.max() > 1)
                                 node.fail_at("tint", "each tint component must lie in [0, 1]");
                             return std::make_unique<DielectricMaterial>(float(ior), parse_roughness(node, 0.0), tint);
                         })

}  // namespace isotrace
