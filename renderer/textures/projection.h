#pragma once
// Projection: where a texture is looked up at a shading point — the surface's uv, the 3-D point itself, or a 2-D
// mapping of it (planar, triplanar, spherical, cylindrical), in object or world space, optionally placed by a
// transform. docs/textures.md, "Projections".
#include <array>

#include "renderer/math/transform.h"
#include "renderer/plugin/texture.h"

namespace isotrace {

class SceneNode;

enum class ProjectionKind { Uv, Solid, Planar, Triplanar, Spherical, Cylindrical };

// One point to look the texture up at, and its weight in the result (the weights of a projection's lookups sum
// to one; only triplanar has more than one).
struct ProjectedPoint {
    Vec3f point;  // 2-D projections: (u, v, 0)
    float weight = 1;
};

struct ProjectedLookups {
    std::array<ProjectedPoint, 3> points;
    int count = 1;
    // The footprint's width along the lookups' first and second coordinates, in their units.
    std::array<float, 2> footprint{0, 0};
};

struct ProjectionSettings {
    ProjectionKind kind = ProjectionKind::Uv;
    int axis = 2;  // planar, spherical and cylindrical: the axis the mapping looks along or turns about
    float sharpness = 4;  // triplanar: the weights are |n_i|^sharpness, normalised
    bool object_space = true;
    Transform placement{};  // the texture's placement in its space (identity: none)
};

class Projection {
public:
    explicit Projection(const ProjectionSettings& settings, const TextureNeeds& uv_need = {});

    ProjectedLookups project(const TextureContext& context) const;
    bool is_2d() const { return kind_ != ProjectionKind::Solid; }
    // A uv projection needs uv on the surface.
    TextureNeeds needs() const { return needs_; }

private:
    Vec3f to_texture_point(const Vec3f& p) const { return placed_ ? Vec3f(placement_.inverse_point(Vec3d(p))) : p; }
    std::array<float, 2> planar(const Vec3f& p, int axis) const {
        return {p[(axis + 1) % 3], p[(axis + 2) % 3]};
    }

    ProjectionKind kind_;
    int axis_;
    float sharpness_;
    bool object_space_;
    bool placed_;
    Transform placement_;
    float footprint_scale_;  // how much the placement shrinks lengths (1 / its scale)
    TextureNeeds needs_;
};

// parent[key]: "uv", "solid", ... or {"type": ..., "axis", "sharpness", "space", "transform"}; absent: `fallback`.
Projection parse_projection(const SceneNode& parent, const std::string& key, ProjectionKind fallback);

}  // namespace isotrace
