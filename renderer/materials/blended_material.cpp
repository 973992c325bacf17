#include "renderer/materials/blended_material.h"

#include <cassert>

#include "renderer/bsdf/principled_bsdf.h"
#include "renderer/plugin/surface_hit.h"

namespace isotrace {
namespace {

class BlendedMaterial final : public Material {
public:
    explicit BlendedMaterial(std::vector<const Material*> parts) : parts_(std::move(parts)) {
        for (const Material* part : parts_) {
            assert(part->can_blend());
            emissive_ = emissive_ || part->is_emissive();
        }
    }

    Rgb albedo(const SurfaceHit& hit) const override {
        return sum(hit, [&](const Material& m) { return m.albedo(hit); }, Rgb());
    }
    Rgb emission(const SurfaceHit& hit, const Vec3f& towards_viewer) const override {
        if (!emissive_) return {};
        return sum(hit, [&](const Material& m) { return m.emission(hit, towards_viewer); }, Rgb());
    }
    bool is_emissive() const override { return emissive_; }
    SurfaceBsdf bsdf(const SurfaceHit& hit) const override { return PrincipledBsdf(principled_parameters(hit)); }
    PrincipledParameters principled_parameters(const SurfaceHit& hit) const override {
        PrincipledParameters zero;
        for_each_principled_parameter(zero, zero, [](auto& value, auto&) { value = {}; });
        return sum(hit, [&](const Material& m) { return m.principled_parameters(hit); }, zero);
    }
    void perturb_normal(SurfaceHit& hit) const override {
        const SurfaceHit unperturbed = hit;
        const auto perturbed = [&](const Material& m) {
            SurfaceHit own = unperturbed;
            m.perturb_normal(own);
            return std::array{own.shading_normal, own.tangent};
        };
        const auto frame = sum(hit, perturbed, std::array<Vec3f, 2>{});
        hit.shading_normal = safe_normalize(frame[0], unperturbed.shading_normal);
        hit.tangent = frame[1];
    }
    TextureNeeds texture_needs() const override {
        TextureNeeds needs;
        for (const Material* part : parts_) needs |= part->texture_needs();
        return needs;
    }

private:
    // Σ weight · value(part material) over the hit's blend.
    template <class Value, class T>
    T sum(const SurfaceHit& hit, const Value& value, T total) const {
        for (int k = 0; k < hit.blend.count; ++k) {
            const float w = hit.blend.weight[std::size_t(k)];
            const Material& part = *parts_[hit.blend.part[std::size_t(k)]];
            total = add(total, value(part), w);
        }
        return total;
    }
    static Rgb add(const Rgb& total, const Rgb& value, float w) { return total + value * w; }
    static PrincipledParameters add(PrincipledParameters total, const PrincipledParameters& value, float w) {
        for_each_principled_parameter(total, value, [w](auto& sum, const auto& term) { sum = sum + term * w; });
        return total;
    }
    static std::array<Vec3f, 2> add(const std::array<Vec3f, 2>& total, const std::array<Vec3f, 2>& value, float w) {
        return {total[0] + value[0] * w, total[1] + value[1] * w};
    }

    std::vector<const Material*> parts_;
    bool emissive_ = false;
};

}  // namespace

std::unique_ptr<Material> make_blended_material(std::vector<const Material*> parts) {
    return std::make_unique<BlendedMaterial>(std::move(parts));
}

}  // namespace isotrace
