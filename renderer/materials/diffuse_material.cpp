// Lambertian reflector with an optional emission term. The reflectance may be an image texture.
#include <algorithm>

#include "renderer/plugin/material.h"
#include "renderer/textures/colour_source.h"

namespace isotrace {
namespace {

class DiffuseMaterial final : public Material {
public:
    DiffuseMaterial(ColourSource reflectance, const Rgb& emission)
        : reflectance_(std::move(reflectance)), emission_(emission) {}

    Rgb albedo(const SurfaceHit& hit) const override {
        const Rgb r = reflectance_.evaluate(hit);  // textures may stray outside [0, 1]: keep energy conserved
        return {std::clamp(r.r, 0.0f, 1.0f), std::clamp(r.g, 0.0f, 1.0f), std::clamp(r.b, 0.0f, 1.0f)};
    }
    Rgb emission(const SurfaceHit&) const override { return emission_; }

private:
    ColourSource reflectance_;
    Rgb emission_;
};

std::unique_ptr<Material> create(const SceneNode& node) {
    ColourSource reflectance = parse_colour_source(node, "reflectance", Rgb(0.5f));
    const Rgb r = reflectance.scale();
    if (reflectance.is_constant() && (r.r < 0 || r.g < 0 || r.b < 0 || r.max() > 1))
        node.fail_at("reflectance", "each reflectance component must lie in [0, 1] (energy conservation)");
    const Rgb emission = node.colour_or("emission", Rgb(0.0f));
    if (emission.r < 0 || emission.g < 0 || emission.b < 0) node.fail_at("emission", "emission must not be negative");
    return std::make_unique<DiffuseMaterial>(std::move(reflectance), emission);
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(material_registry, "diffuse",
                         "Lambertian; reflectance (colour or {texture, space, scale}, default 0.5), emission", create)

}  // namespace isotrace
