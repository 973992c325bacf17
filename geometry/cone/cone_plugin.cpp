// The "cone" plugin: a cone or, with two radii, a truncated cone (frustum), capped or open.
#include "geometry/cone/frustum_shape.h"

namespace isotrace {
namespace {

std::unique_ptr<Shape> create(const SceneNode& node) {
    const Vec3d base = node.vec3_or("base", {0, 0, 0});
    const double base_radius = node.number_or("base_radius", 1.0, NumberRange::non_negative());
    const bool caps = node.boolean_or("caps", true);
    Vec3d top;
    double top_radius = 0;
    std::string top_key = "top";
    if (node.has("apex")) {
        if (node.has("top") || node.has("top_radius"))
            node.fail_at("apex", "give either \"apex\" or \"top\" and \"top_radius\", not both");
        top = node.vec3("apex");
        top_key = "apex";
    } else {
        top = node.vec3_or("top", {0, 1, 0});
        top_radius = node.number_or("top_radius", 0.0, NumberRange::non_negative());
    }
    if (!(base_radius > 0) && !(top_radius > 0)) node.fail_at("base_radius", "one of the two radii must be positive");
    return std::make_unique<FrustumShape>(
        "cone", frustum_from_end_points(node, top_key, base, top, base_radius, top_radius, caps));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "cone",
                         "cone or truncated cone; base, base_radius, apex or top and top_radius, caps", create)

}  // namespace isotrace
