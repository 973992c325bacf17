#include "renderer/plugin/camera.h"
#include "renderer/scene/transform_parser.h"

namespace isotrace {

Transform parse_camera_placement(const SceneNode& node) {
    if (node.has("look_at") && node.has("transform"))
        node.fail_at("transform", "give either \"look_at\" or \"transform\", not both");
    if (auto look_at = node.optional_object("look_at")) {
        const Vec3d eye = look_at->vec3("eye");
        const Vec3d target = look_at->vec3("target");
        const Vec3d up = look_at->vec3_or("up", {0, 1, 0});
        look_at->finish();
        try {
            return Transform::look_at(eye, target, up);
        } catch (const std::invalid_argument& error) {
            look_at->fail(error.what());
        }
    }
    if (!node.has("transform")) node.fail("a camera needs \"look_at\" or \"transform\"");
    return parse_optional_transform(node, "transform");
}

}  // namespace isotrace
