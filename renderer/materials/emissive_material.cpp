// Area emitter: radiance * scale leaves the front side (both sides with "two_sided"), nothing is reflected.
// Emissive objects whose shape can be sampled become area lights.
#include "renderer/materials/emission_profile.h"
#include "renderer/plugin/material.h"

namespace isotrace {
namespace {

class EmissiveMaterial final : public Material {
public:
    explicit EmissiveMaterial(const EmissionProfile& emission) : emission_(emission) {}
    Rgb albedo(const SurfaceHit&) const override { return {}; }
    Rgb emission(const SurfaceHit& hit, const Vec3f& towards_viewer) const override {
        return emission_.towards(hit, towards_viewer);
    }
    bool is_emissive() const override { return emission_.emits(); }

private:
    EmissionProfile emission_;
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(material_registry, "emissive",
                         "area emitter; radiance (colour), scale (default 1), two_sided (default false)",
                         [](const SceneNode& node) -> std::unique_ptr<Material> {
                             return std::make_unique<EmissiveMaterial>(
                                 parse_emission(node, "radiance", true, "two_sided", "scale"));
                         })

}  // namespace isotrace
