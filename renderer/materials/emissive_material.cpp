// Pure emitter: radiance * scale leaves the surface, nothing is reflected.
#include "renderer/plugin/material.h"

namespace isotrace {
namespace {

class EmissiveMaterial final : public Material {
public:
    explicit EmissiveMaterial(const Rgb& radiance) : radiance_(radiance) {}
    Rgb albedo(const SurfaceHit&) const override { return {}; }
    Rgb emission(const SurfaceHit&) const override { return radiance_; }

private:
    Rgb radiance_;
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(material_registry, "emissive", "area emitter; radiance (colour), scale (default 1)",
                         [](const SceneNode& node) -> std::unique_ptr<Material> {
                             const Rgb radiance = node.colour("radiance");
                             const double scale = node.number_or("scale", 1.0, NumberRange::non_negative());
                             if (radiance.r < 0 || radiance.g < 0 || radiance.b < 0)
                                 node.fail_at("radiance", "radiance must not be negative");
                             return std::make_unique<EmissiveMaterial>(radiance * float(scale));
                         })

}  // namespace isotrace
