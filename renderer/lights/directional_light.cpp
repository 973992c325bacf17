// Distant light (sun-like): parallel light arriving from one direction with a given irradiance.
#include <limits>
#include <numbers>

#include "renderer/params/emitted_colour.h"
#include "renderer/params/world_limit.h"
#include "renderer/plugin/light.h"

namespace isotrace {
namespace {

class DirectionalLight final : public Light {
public:
    DirectionalLight(const Vec3f& towards_light, const Rgb& irradiance)
        : towards_light_(towards_light), irradiance_(irradiance) {}

    bool is_delta() const override { return true; }
    LightSample sample(const Vec3f&, std::array<float, 2>) const override {
        return {towards_light_, std::numeric_limits<float>::infinity(), irradiance_, 1.0f, true};
    }
    // The light crossing the scene's bounding disk.
    float power() const override {
        return saturated_power(std::numbers::pi * double(scene_radius_) * scene_radius_ * irradiance_.max());
    }
    void preprocess(const Bounds3f& scene_bounds) override { scene_radius_ = scene_bounds.bounding_radius(); }

private:
    Vec3f towards_light_;
    Rgb irradiance_;
    float scene_radius_ = 0;
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(light_registry, "directional",
                         "distant light; direction (travel direction of the light), irradiance (colour), scale",
                         [](const SceneNode& node) -> std::unique_ptr<Light> {
                             const Vec3d direction = unit_direction(node, "direction");
                             const Rgb irradiance = emitted_colour(node, "irradiance", Rgb(1.0f), "scale");
                             return std::make_unique<DirectionalLight>(Vec3f(-direction), irradiance);
                         })

}  // namespace isotrace
