// The "cylinder" plugin: a frustum (geometry/cone) whose two radii are equal.
#include "geometry/cone/frustum_shape.h"

namespace isotrace {
namespace {

std::unique_ptr<Shape> create(const SceneNode& node) {
    const Vec3d base = node.vec3_or("base", {0, 0, 0});
    const Vec3d top = node.vec3_or("top", {0, 1, 0});
    const double radius = node.number_or("radius", 1.0, NumberRange::positive());
    const bool caps = node.boolean_or("caps", true);
    return std::make_unique<FrustumShape>("cylinder", frustum_from_end_points(node, "top", base, top, radius, radius, caps));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "cylinder", "circular cylinder; base, top, radius, caps", create)

}  // namespace isotrace
