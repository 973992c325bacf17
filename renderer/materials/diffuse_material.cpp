// Lambertian reflector. The reflectance may be an image texture.
#include <algorithm>

#include "renderer/plugin/material.h"
#include "renderer/textures/colour_source.h"

namespace isotrace {
namespace {

class DiffuseMaterial final : public Material {
public:
    explicit DiffuseMaterial(ColourSource reflectance) : reflectance_(std::move(reflectance)) {}

    Rgb albedo(const SurfaceHit& hit) const override {
        const Rgb r = reflectance_.evaluate(hit);  // textures may stray outside [0, 1]: keep energy conserved
        return {std::clamp(r.r, 0.0f, 1.0f), std::clamp(r.g, 0.0f, 1.0f), std::clamp(r.b, 0.0f, 1.0f)};
    }

private:
    ColourSource reflectance_;
};

std::unique_ptr<Material> create(const SceneNode& node) {
    ColourSource reflectance = parse_colour_source(node, "reflectance", Rgb(0.5f));
    const Rgb r = reflectance.scale();
    if (reflectance.is_constant() && (r.r < 0 || r.g < 0 || r.b < 0 || r.max() > 1))
        node.fail_at("reflectance", "each reflectance component must lie in [0, 1] (energy conservation)");
    return std::make_unique<DiffuseMaterial>(std::move(reflectance));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(material_registry, "diffuse",
                         "Lambertian; reflectance (colour or {texture, space, scale}, default 0.5)", create)

}  // namespace isotrace
