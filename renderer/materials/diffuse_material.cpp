// Lambertian reflector with an optional emission term.
#include "renderer/plugin/material.h"

namespace isotrace {
namespace {

class DiffuseMaterial final : public Material {
public:
    DiffuseMaterial(const Rgb& reflectance, const Rgb& emission) : reflectance_(reflectance), emission_(emission) {}
    Rgb albedo(const SurfaceHit&) const override { return reflectance_; }
    Rgb emission(const SurfaceHit&) const override { return emission_; }

private:
    Rgb reflectance_;
    Rgb emission_;
};

Rgb checked_reflectance(const SceneNode& node) {
    const Rgb r = node.colour_or("reflectance", Rgb(0.5f));
    if (r.r < 0 || r.g < 0 || r.b < 0 || r.max() > 1)
        node.fail_at("reflectance", "each reflectance component must lie in [0, 1] (energy conservation)");
    return r;
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(material_registry, "diffuse", "Lambertian; reflectance (colour, default 0.5), emission",
                         [](const SceneNode& node) -> std::unique_ptr<Material> {
                             const Rgb reflectance = checked_reflectance(node);
                             const Rgb emission = node.colour_or("emission", Rgb(0.0f));
                             if (emission.r < 0 || emission.g < 0 || emission.b < 0)
                                 node.fail_at("emission", "emission must not be negative");
                             return std::make_unique<DiffuseMaterial>(reflectance, emission);
                         })

}  // namespace isotrace
