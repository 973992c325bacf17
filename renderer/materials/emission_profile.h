#pragma once
// Emitted radiance of a surface: uniform over directions (Lambertian emitter), from the front side only (the
// geometric normal's side: counter-clockwise triangles, the outside of spheres) unless two-sided.
#include "renderer/math/rgb.h"
#include "renderer/params/scene_node.h"
#include "renderer/plugin/surface_hit.h"

namespace isotrace {

struct EmissionProfile {
    Rgb radiance;
    bool two_sided = false;

    Rgb towards(const SurfaceHit& hit, const Vec3f& towards_viewer) const {
        return two_sided || dot(hit.geometric_normal, towards_viewer) > 0 ? radiance : Rgb();
    }
    bool emits() const { return !radiance.is_black(); }
};

// Reads the radiance colour node[radiance_key] (absent = black unless required) times node[scale_key] (none when
// empty), within the limits of emitted_colour, and node[two_sided_key].
EmissionProfile parse_emission(const SceneNode& node, const std::string& radiance_key, bool required,
                               const std::string& two_sided_key, const std::string& scale_key = "");

}  // namespace isotrace
