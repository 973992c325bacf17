// Principled material: one model for most surfaces (renderer/bsdf/principled_bsdf.h), every parameter of which
// may be a texture (docs/textures.md), with bump or normal mapping and emission.
#include <cmath>
#include <numbers>

#include "renderer/bsdf/principled_bsdf.h"
#include "renderer/materials/normal_perturbation.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/scene_object.h"
#include "renderer/textures/texture_at_hit.h"
#include "renderer/textures/texture_parser.h"

namespace isotrace {
namespace {

// A texture for each of PrincipledParameters' members (same names, for for_each_principled_parameter), and for the
// parameters the material handles itself.
struct PrincipledTextures {
    ColourTexturePtr base_colour;
    ScalarTexturePtr metallic, roughness, anisotropy, ior, specular, transmission, clearcoat, clearcoat_roughness,
        sheen, sheen_roughness;
    ColourTexturePtr sheen_colour;
    ScalarTexturePtr anisotropy_rotation;
    ColourTexturePtr emission;
};

class PrincipledMaterial final : public Material {
public:
    PrincipledMaterial(PrincipledTextures textures, float emission_strength, bool two_sided_emission,
                       NormalPerturbation perturbation)
        : textures_(std::move(textures)),
          emission_strength_(emission_strength),
          two_sided_emission_(two_sided_emission),
          perturbation_(std::move(perturbation)),
          constant_(constant_parameters()) {
        const std::optional<Rgb> emission = textures_.emission->constant();
        emits_ = emission_strength_ > 0 && (!emission || !emission->is_black());
        const std::optional<float> anisotropy = textures_.anisotropy->constant();
        anisotropic_ = !anisotropy || *anisotropy > 0;
    }

    Rgb albedo(const SurfaceHit& hit) const override {
        return texture_at_hit(*textures_.base_colour, hit);
    }
    Rgb emission(const SurfaceHit& hit, const Vec3f& towards_viewer) const override {
        if (!emits_ || (!two_sided_emission_ && dot(hit.geometric_normal, towards_viewer) <= 0)) return {};
        return texture_at_hit(*textures_.emission, hit) * emission_strength_;
    }
    bool is_emissive() const override { return emits_; }
    SurfaceBsdf bsdf(const SurfaceHit& hit) const override { return PrincipledBsdf(principled_parameters(hit)); }
    void perturb_normal(SurfaceHit& hit) const override {
        if (perturbation_.perturbs()) perturbation_.apply(hit);
        if (anisotropic_) hit.tangent = brushing_direction(hit);
    }
    bool can_blend() const override { return true; }
    PrincipledParameters principled_parameters(const SurfaceHit& hit) const override {
        return constant_ ? *constant_ : parameters(TextureContext(hit));
    }
    TextureNeeds texture_needs() const override {
        TextureNeeds needs = perturbation_.needs();
        PrincipledParameters unused;
        for_each_principled_parameter(textures_, unused,
                                      [&](const auto& texture, auto&) { needs |= texture->needs(); });
        needs |= textures_.anisotropy_rotation->needs();
        needs |= textures_.emission->needs();
        return needs;
    }

private:
    PrincipledParameters parameters(const TextureContext& at) const {
        PrincipledParameters p;
        for_each_principled_parameter(textures_, p,
                                      [&](const auto& texture, auto& value) { value = texture->evaluate(at); });
        return p;
    }

    // The parameters when no texture varies, evaluated once.
    std::optional<PrincipledParameters> constant_parameters() const {
        bool constant = true;
        PrincipledParameters unused;
        for_each_principled_parameter(textures_, unused,
                                      [&](const auto& texture, auto&) { constant = constant && texture->constant(); });
        return constant ? std::optional(parameters(TextureContext())) : std::nullopt;
    }

    // The direction anisotropic roughness stretches along: dp/du where the surface has uv, else around the
    // object's z axis (brushed in circles), turned by anisotropy_rotation (in turns).
    Vec3f brushing_direction(const SurfaceHit& hit) const {
        const Vec3f n = hit.shading_normal;
        Vec3f direction = hit.dpdu;
        if (!(dot(direction, direction) > 0)) {
            const TextureContext at(hit);
            const Vec3f around_z = cross(Vec3f(0, 0, 1), at.object_normal);
            std::optional<Transform> computed;
            direction = hit.to_world(computed).vector(around_z);
        }
        Vec3f tangent = direction - n * dot(n, direction);
        if (!(dot(tangent, tangent) > 0)) return {};
        tangent = normalize(tangent);
        const float turns = texture_at_hit(*textures_.anisotropy_rotation, hit);
        if (turns == 0) return tangent;
        const float angle = 2 * std::numbers::pi_v<float> * turns;
        return tangent * std::cos(angle) + cross(n, tangent) * std::sin(angle);
    }

    PrincipledTextures textures_;
    float emission_strength_;
    bool two_sided_emission_;
    NormalPerturbation perturbation_;
    std::optional<PrincipledParameters> constant_;
    bool emits_ = false;
    bool anisotropic_ = false;
};

std::unique_ptr<Material> create(const SceneNode& node) {
    const NumberRange unit = NumberRange::unit_interval();
    PrincipledTextures t;
    t.base_colour = parse_colour_texture(node, "base_colour", Rgb(0.8f), ColourRange::Reflectance);
    t.metallic = parse_scalar_texture(node, "metallic", 0, unit);
    t.roughness = parse_scalar_texture(node, "roughness", 0.5f, unit);
    t.anisotropy = parse_scalar_texture(node, "anisotropy", 0, unit);
    t.anisotropy_rotation = parse_scalar_texture(node, "anisotropy_rotation", 0, unit);
    t.ior = parse_scalar_texture(node, "ior", 1.5f, {1.0, 10.0, true, false});
    t.specular = parse_scalar_texture(node, "specular", 1, unit);
    t.transmission = parse_scalar_texture(node, "transmission", 0, unit);
    t.clearcoat = parse_scalar_texture(node, "clearcoat", 0, unit);
    t.clearcoat_roughness = parse_scalar_texture(node, "clearcoat_roughness", 0.03f, unit);
    t.sheen = parse_scalar_texture(node, "sheen", 0, unit);
    t.sheen_colour = parse_colour_texture(node, "sheen_colour", Rgb(1.0f), ColourRange::Reflectance);
    t.sheen_roughness = parse_scalar_texture(node, "sheen_roughness", 0.5f, unit);
    t.emission = parse_colour_texture(node, "emission", Rgb(), ColourRange::Emission);
    const double strength = node.number_or("emission_strength", 1.0, {0, 1e30, false, false});
    const bool two_sided = node.boolean_or("two_sided_emission", false);
    NormalPerturbation perturbation = parse_normal_perturbation(node);
    return std::make_unique<PrincipledMaterial>(std::move(t), float(strength), two_sided, std::move(perturbation));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(material_registry, "principled",
                         "base_colour, metallic, roughness, anisotropy, anisotropy_rotation, ior, specular, "
                         "transmission, clearcoat, clearcoat_roughness, sheen, sheen_colour, sheen_roughness, "
                         "emission, emission_strength, two_sided_emission, bump, bump_height, normal_map, "
                         "normal_strength (each parameter a constant or a texture)",
                         create)

}  // namespace isotrace
