#include "renderer/materials/normal_perturbation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/params/world_limit.h"
#include "renderer/plugin/scene_object.h"
#include "renderer/textures/texture_parser.h"

namespace isotrace {
namespace {

// The uv step that moves the point by the world-space `offset` along the surface (least squares on dp/du, dp/dv;
// zero where they are degenerate).
std::array<float, 2> uv_step(const SurfaceHit& hit, const Vec3f& offset) {
    const float a = dot(hit.dpdu, hit.dpdu), b = dot(hit.dpdu, hit.dpdv), c = dot(hit.dpdv, hit.dpdv);
    const float determinant = a * c - b * b;
    if (!(std::abs(determinant) > 1e-20f * std::max(a * c, 1e-30f))) return {0, 0};
    const float pu = dot(offset, hit.dpdu), pv = dot(offset, hit.dpdv);
    return {(c * pu - b * pv) / determinant, (a * pv - b * pu) / determinant};
}

// The texture context at the hit moved by `offset` (world space) along the surface; `to_world` is the hit's.
TextureContext moved(const TextureContext& at, const SurfaceHit& hit, const Transform& to_world, const Vec3f& offset) {
    TextureContext result = at;
    const Vec3f object_offset = Vec3f(to_world.inverse_vector(Vec3d(offset)));
    result.position = at.position + offset;
    result.object_position = at.object_position + object_offset;
    result.shape_position = at.shape_position + Vec3d(hit.object && hit.object->instanced ? object_offset : offset);
    const std::array<float, 2> step = uv_step(hit, offset);
    result.uv = {at.uv[0] + step[0], at.uv[1] + step[1]};
    return result;
}

}  // namespace

NormalPerturbation::NormalPerturbation(ScalarTexturePtr bump, float bump_height, ColourTexturePtr normal_map,
                                       float normal_strength)
    : bump_(std::move(bump)),
      bump_height_(bump_height),
      normal_map_(std::move(normal_map)),
      normal_strength_(normal_strength) {}

void NormalPerturbation::apply(SurfaceHit& hit) const {
    Vec3f normal = hit.shading_normal;
    if (normal_map_) normal = normal_mapped(hit, normal);
    if (bump_) normal = bumped(hit, normal);
    hit.shading_normal = keep_above_surface(normal, hit.geometric_normal);
}

Vec3f NormalPerturbation::bumped(const SurfaceHit& hit, const Vec3f& normal) const {
    // Forward differences over half a pixel's footprint (so the bump is as smooth as the image can show), or a
    // small share of the point's magnitude where the ray carries no footprint.
    const float step = std::max(0.5f * hit.footprint, 1e-4f * (max_component(abs(hit.position)) + 1e-3f));
    Vec3f tangent, bitangent;
    orthonormal_basis(normal, tangent, bitangent);
    const TextureContext here(hit);
    std::optional<Transform> computed;
    const Transform& to_world = hit.to_world(computed);
    const float height = bump_->evaluate(here);
    const float along_tangent = bump_->evaluate(moved(here, hit, to_world, tangent * step)) - height;
    const float along_bitangent = bump_->evaluate(moved(here, hit, to_world, bitangent * step)) - height;
    // The surface raised by h along its normal has the normal n − ∇h (curvature terms dropped).
    const Vec3f slope = (tangent * along_tangent + bitangent * along_bitangent) * (bump_height_ / step);
    return safe_normalize(normal - slope, normal);
}

Vec3f NormalPerturbation::normal_mapped(const SurfaceHit& hit, const Vec3f& normal) const {
    const Vec3f u_direction = hit.dpdu - normal * dot(normal, hit.dpdu);
    if (!(dot(u_direction, u_direction) > 0)) return normal;  // no uv frame here
    const Vec3f tangent = normalize(u_direction);
    Vec3f bitangent = cross(normal, tangent);
    if (dot(bitangent, hit.dpdv) < 0) bitangent = -bitangent;  // mirrored uv
    const Rgb stored = normal_map_->evaluate(TextureContext(hit));
    const Vec3f m(normal_strength_ * (2 * stored.r - 1), normal_strength_ * (2 * stored.g - 1), 2 * stored.b - 1);
    return safe_normalize(tangent * m.x + bitangent * m.y + normal * std::max(m.z, 0.0f), normal);
}

TextureNeeds NormalPerturbation::needs() const {
    TextureNeeds needs;
    if (normal_map_) needs |= normal_map_->needs();
    if (bump_) needs |= bump_->needs();
    return needs;
}

Vec3f keep_above_surface(const Vec3f& normal, const Vec3f& geometric_normal) {
    static const float min_cosine = float(std::cos(NormalPerturbation::kMaxTiltDegrees * std::numbers::pi / 180));
    const float cosine = dot(normal, geometric_normal);
    if (cosine >= min_cosine) return normal;
    // Keep the direction of the tilt, at the largest tilt allowed.
    const Vec3f along_surface = normal - geometric_normal * cosine;
    const float length_along = length(along_surface);
    if (!(length_along > 0)) return geometric_normal;
    const float sine = std::sqrt(1 - min_cosine * min_cosine);
    return normalize(along_surface * (sine / length_along) + geometric_normal * min_cosine);
}

NormalPerturbation parse_normal_perturbation(const SceneNode& node) {
    ScalarTexturePtr bump;
    if (node.has("bump")) bump = parse_scalar_texture(node, "bump", 0, {});
    const double height = node.number_or("bump_height", 0.01, world_length(true));
    ColourTexturePtr normal_map;
    if (node.has("normal_map")) normal_map = parse_data_texture(node, "normal_map");
    const double strength = node.number_or("normal_strength", 1.0, NumberRange::between(0, 10));
    return {std::move(bump), float(height), std::move(normal_map), float(strength)};
}

}  // namespace isotrace
