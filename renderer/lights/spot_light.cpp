// Spot light: a point light whose intensity is limited to a cone around its axis, with a smooth falloff
// (smoothstep in cos θ) between the inner angle (full intensity) and the outer angle (dark).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/params/emitted_colour.h"
#include "renderer/params/world_limit.h"
#include "renderer/plugin/light.h"

namespace isotrace {
namespace {

float smoothstep(float edge0, float edge1, float x) {
    if (edge0 == edge1) return x >= edge1 ? 1.0f : 0.0f;
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3 - 2 * t);
}

class SpotLight final : public Light {
public:
    SpotLight(const Vec3f& position, const Vec3f& axis, const Rgb& intensity, float cos_outer, float cos_inner)
        : position_(position), axis_(axis), intensity_(intensity), cos_outer_(cos_outer), cos_inner_(cos_inner) {}

    bool is_delta() const override { return true; }
    LightSample sample(const Vec3f& point, std::array<float, 2>) const override {
        const Vec3f offset = position_ - point;
        const float distance_squared = dot(offset, offset);
        const float distance = std::sqrt(distance_squared);
        const Vec3f towards_light = offset / distance;
        const float falloff = smoothstep(cos_outer_, cos_inner_, dot(-towards_light, axis_));
        return {towards_light, distance, intensity_ * (falloff / distance_squared), 1.0f, true};
    }
    // Integral of the falloff over the sphere, approximated by the cone half-way between the two angles.
    float power() const override {
        return float(2 * std::numbers::pi) * (1 - 0.5f * (cos_inner_ + cos_outer_)) * intensity_.max();
    }

private:
    Vec3f position_, axis_;
    Rgb intensity_;
    float cos_outer_, cos_inner_;
};

std::unique_ptr<Light> create(const SceneNode& node) {
    const Vec3d position = world_point(node, "position");
    if (node.has("direction") == node.has("target")) node.fail("give either \"direction\" or \"target\"");
    const Vec3d axis = node.has("direction")
                           ? unit_direction(node, "direction")
                           : unit_direction(node, world_point(node, "target") - position, "the spot light's axis");
    const double outer = node.number_or("cone_angle", 30.0, {0, 180, true, false});
    const double inner = node.number_or("falloff_start", outer * 0.8, NumberRange::between(0, 180));
    if (inner > outer) node.fail_at("falloff_start", "falloff_start must not exceed cone_angle");
    const Rgb intensity = emitted_colour(node, "intensity", Rgb(1.0f), "scale");
    const auto cos_degrees = [](double degrees) { return float(std::cos(degrees * std::numbers::pi / 180.0)); };
    return std::make_unique<SpotLight>(Vec3f(position), Vec3f(axis), intensity, cos_degrees(outer),
                                       cos_degrees(inner));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(light_registry, "spot",
                         "spot light; position, direction or target, intensity (colour), scale, cone_angle "
                         "(half-angle, degrees, 30), falloff_start (half-angle of full intensity, 0.8 cone_angle)",
                         create)

}  // namespace isotrace
