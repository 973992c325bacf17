// Area emitter: radiance * scale leaves the front side (the geometric normal's side; both sides with
// "two_sided"), nothing is reflected. Emissive objects whose shape can be sampled become area lights.
#include "renderer/plugin/material.h"
#include "renderer/scene/surface_hit.h"

namespace isotrace {
namespace {

class EmissiveMaterial final : public Material {
public:
    EmissiveMaterial(const Rgb& radiance, bool two_sided) : radiance_(radiance), two_sided_(two_sided) {}
    Rgb albedo(const SurfaceHit&) const override { return {}; }
    Rgb emission(const SurfaceHit& hit, const Vec3f& towards_viewer) const override {
        return two_sided_ || dot(hit.geometric_normal, towards_viewer) > 0 ? radiance_ : Rgb();
    }
    bool is_emissive() const override { return !radiance_.is_black(); }

private:
    Rgb radiance_;
    bool two_sided_;
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(material_registry, "emissive",
                         "area emitter; radiance (colour), scale (default 1), two_sided (default false)",
                         [](const SceneNode& node) -> std::unique_ptr<Material> {
                             const Rgb radiance = node.colour("radiance");
                             const double scale = node.number_or("scale", 1.0, NumberRange::non_negative());
                             if (radiance.r < 0 || radiance.g < 0 || radiance.b < 0)
                                 node.fail_at("radiance", "radiance must not be negative");
                             return std::make_unique<EmissiveMaterial>(radiance * float(scale),
                                                                       node.boolean_or("two_sided", false));
                         })

}  // namespace isotrace
