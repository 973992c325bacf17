// Isotropic point light: intensity (W/sr-like, in the working space) falling off with the squared distance.
#include <numbers>

#include "renderer/params/emitted_colour.h"
#include "renderer/params/world_limit.h"
#include "renderer/plugin/light.h"

namespace isotrace {
namespace {

class PointLight final : public Light {
public:
    PointLight(const Vec3f& position, const Rgb& intensity) : position_(position), intensity_(intensity) {}

    bool is_delta() const override { return true; }
    LightSample sample(const Vec3f& point, std::array<float, 2>) const override {
        const Vec3f offset = position_ - point;
        const float distance_squared = dot(offset, offset);
        const float distance = std::sqrt(distance_squared);
        return {offset / distance, distance, intensity_ * (1.0f / distance_squared), 1.0f, true};
    }
    float power() const override { return float(4 * std::numbers::pi) * intensity_.max(); }

private:
    Vec3f position_;
    Rgb intensity_;
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(light_registry, "point", "point light; position, intensity (colour), scale",
                         [](const SceneNode& node) -> std::unique_ptr<Light> {
                             const Vec3d position = world_point(node, "position");
                             const Rgb intensity = emitted_colour(node, "intensity", Rgb(1.0f), "scale");
                             return std::make_unique<PointLight>(Vec3f(position), intensity);
                         })

}  // namespace isotrace
