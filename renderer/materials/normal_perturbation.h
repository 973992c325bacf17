#pragma once
// Bump and normal maps: a material's shading normal bent by a height texture (any surface, implicit ones
// included) or by a tangent-space normal map (surfaces with uv). The result never leans further than
// kMaxTiltDegrees from the geometric normal, so a shading normal never points below the true surface.
#include "renderer/params/scene_node.h"
#include "renderer/plugin/surface_hit.h"
#include "renderer/plugin/texture.h"

namespace isotrace {

class NormalPerturbation {
public:
    static constexpr float kMaxTiltDegrees = 87;

    NormalPerturbation() = default;
    NormalPerturbation(ScalarTexturePtr bump, float bump_height, ColourTexturePtr normal_map, float normal_strength);

    bool perturbs() const { return bump_ || normal_map_; }
    // Replaces hit.shading_normal by the perturbed normal.
    void apply(SurfaceHit& hit) const;
    TextureNeeds needs() const;

private:
    Vec3f bumped(const SurfaceHit& hit, const Vec3f& normal) const;
    Vec3f normal_mapped(const SurfaceHit& hit, const Vec3f& normal) const;

    ScalarTexturePtr bump_;  // height; a value of 1 raises the surface by bump_height_ world units along its normal
    float bump_height_ = 0;
    ColourTexturePtr normal_map_;  // tangent space (x along dp/du, y along dp/dv, z the normal), stored as (n + 1) / 2
    float normal_strength_ = 1;
};

// Reads node["bump"] (a scalar texture), node["bump_height"] (world units, default 0.01), node["normal_map"] (a data
// image) and node["normal_strength"] (default 1).
NormalPerturbation parse_normal_perturbation(const SceneNode& node);

// `normal` tilted towards the geometric normal where it leans further than kMaxTiltDegrees from it.
Vec3f keep_above_surface(const Vec3f& normal, const Vec3f& geometric_normal);

}  // namespace isotrace
