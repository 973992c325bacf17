// Metal: smooth mirror or rough GGX conductor with a complex index of refraction, given by element symbol
// ("metal": "Au") or explicitly ("eta", "k" as RGB triples).
#include "renderer/bsdf/conductor_bsdf.h"
#include "renderer/bsdf/conductor_presets.h"
#include "renderer/materials/roughness_parameters.h"
#include "renderer/plugin/material.h"

namespace isotrace {
namespace {

class ConductorMaterial final : public Material {
public:
    ConductorMaterial(const ComplexIor& ior, MicrofacetAlphas alphas) : ior_(ior), alphas_(alphas) {}
    Rgb albedo(const SurfaceHit&) const override { return normal_incidence_reflectance(); }
    SurfaceBsdf bsdf(const SurfaceHit&) const override {
        return ConductorBsdf(ior_, alphas_.x, alphas_.y);
    }

private:
    Rgb normal_incidence_reflectance() const {
        const auto f0 = [](float n, float k) { return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k); };
        return {f0(ior_.eta.r, ior_.k.r), f0(ior_.eta.g, ior_.k.g), f0(ior_.eta.b, ior_.k.b)};
    }
    ComplexIor ior_;
    MicrofacetAlphas alphas_;
};

Rgb positive_triple(const SceneNode& node, const std::string& key) {
    const Vec3d v = node.vec3(key);
    if (!(v.x > 0 && v.y > 0 && v.z > 0)) node.fail_at(key, "every component must be > 0");
    return {float(v.x), float(v.y), float(v.z)};
}

std::unique_ptr<Material> create(const SceneNode& node) {
    ComplexIor ior;
    if (node.has("metal")) {
        if (node.has("eta") || node.has("k")) node.fail_at("metal", "give either \"metal\" or \"eta\" and \"k\"");
        const std::string symbol = node.string("metal");
        const auto preset = find_conductor_preset(symbol);
        if (!preset) {
            std::vector<std::string> known;
            for (const auto& p : conductor_presets()) known.emplace_back(p.symbol);
            std::string list;
            for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
            node.fail_at("metal", "unknown metal \"" + symbol + "\"" + did_you_mean(symbol, known) + "; presets: " + list);
        }
        ior = *preset;
    } else {
        ior = {positive_triple(node, "eta"), {0, 0, 0}};
        const Vec3d k = node.vec3("k");
        if (!(k.x >= 0 && k.y >= 0 && k.z >= 0)) node.fail_at("k", "every component must be >= 0");
        ior.k = {float(k.x), float(k.y), float(k.z)};
    }
    return std::make_unique<ConductorMaterial>(ior, parse_roughness(node, 0.0));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(material_registry, "conductor",
                         "metal; metal (Au, Ag, Cu, ...) or eta + k (RGB), roughness (0 = mirror), roughness_v",
                         create)

}  // namespace isotrace
