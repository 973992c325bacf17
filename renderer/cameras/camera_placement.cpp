#include "renderer/params/transform_parser.h"
#include "renderer/params/world_limit.h"
#include "renderer/plugin/camera.h"

namespace isotrace {

Transform parse_camera_placement(const SceneNode& node) {
    if (node.has("look_at") && node.has("transform"))
        node.fail_at("transform", "give either \"look_at\" or \"transform\", not both");
    if (auto look_at = node.optional_object("look_at")) {
        const Vec3d eye = world_point(*look_at, "eye");
        const Vec3d target = world_point(*look_at, "target");
        const Vec3d up = look_at->has("up") ? unit_direction(*look_at, "up") : Vec3d(0, 1, 0);
        look_at->finish();
        try {
            return Transform::look_at(eye, target, up);
        } catch (const std::invalid_argument& error) {
            look_at->fail(error.what());
        }
    }
    if (!node.has("transform")) node.fail("a camera needs \"look_at\" or \"transform\"");
    const Transform to_world = parse_optional_transform(node, "transform");
    check_reach_within_world(node, "transform", to_world, 0, "the camera's position");
    return to_world;
}

}  // namespace isotrace
