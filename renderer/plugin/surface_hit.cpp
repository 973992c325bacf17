#include "renderer/plugin/surface_hit.h"

#include "renderer/plugin/scene_object.h"

namespace isotrace {

const Transform& SurfaceHit::to_world(std::optional<Transform>& computed) const {
    static const Transform kIdentity;
    if (placement) return computed.emplace(to_world_of_record(*placement));
    return object ? object->to_world : kIdentity;
}

}  // namespace isotrace
