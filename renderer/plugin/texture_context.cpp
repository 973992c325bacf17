#include <cmath>

#include "renderer/plugin/scene_object.h"
#include "renderer/plugin/texture.h"

namespace isotrace {

TextureContext::TextureContext(const SurfaceHit& hit)
    : position(hit.position),
      normal(hit.shading_normal),
      object_position(hit.position),
      object_normal(hit.shading_normal),
      uv(hit.uv),
      dpdu(hit.dpdu),
      dpdv(hit.dpdv),
      footprint(hit.footprint),
      object_footprint(hit.footprint),
      shape_position(hit.position),
      shape_normal(hit.shading_normal) {
    // Without an object (area-light samples, tests) object space is world space.
    const SceneObject* object = hit.object;
    if (!object) return;
    shape = object->shape.get();
    std::optional<Transform> computed;
    const Transform& to_world = hit.to_world(computed);
    const Vec3d p = to_world.inverse_point(Vec3d(hit.position));
    const Vec3d unit_n = safe_normalize(to_world.inverse_normal(Vec3d(hit.shading_normal)), Vec3d(hit.shading_normal));
    object_position = Vec3f(p);
    object_normal = Vec3f(unit_n);
    // A baked shape lives in world space already; an instanced one in object space.
    if (object->instanced) {
        shape_position = p;
        shape_normal = unit_n;
    }
    // The placement's scale: the cube root of its volume change (exact for similarities).
    if (footprint > 0) object_footprint = footprint / float(std::cbrt(std::abs(to_world.determinant())));
}

}  // namespace isotrace
