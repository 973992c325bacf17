#include "renderer/bsdf/dielectric_coating.h"

#include <algorithm>
#include <cmath>

#include "renderer/bsdf/fresnel.h"
#include "renderer/bsdf/microfacet.h"
#include "renderer/bsdf/shading_frame.h"

namespace isotrace {
namespace {

constexpr int kTableSize = 64;
constexpr int kStrata = 32;  // per axis, for each table entry's quadrature over the visible normals

Vec3f direction_at(float mu) {
    return {std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu};
}

}  // namespace

DielectricCoating::DielectricCoating(float eta, float alpha)
    : eta_(eta), smooth_(alpha == 0), ggx_(alpha, alpha) {
    if (!smooth_) {
        // E(wo) = expectation over visible normals m of F(wo.m) G2 / G1(wo) (the microfacet lobe's sampling
        // weight), by a midpoint rule on the square the visible normals are warped from. The lobe is
        // isotropic, so E depends on mu only. mu = 0 itself is degenerate and stands in for a tiny mu.
        reflectance_table_.resize(kTableSize);
        for (int i = 0; i < kTableSize; ++i) {
            const float t = float(i) / (kTableSize - 1);
            const Vec3f wo = direction_at(std::max(t * t, 1e-4f));
            double sum = 0;
            for (int a = 0; a < kStrata; ++a) {
                for (int b = 0; b < kStrata; ++b) {
                    const Vec3f m = ggx_.sample_visible_normal(wo, {(a + 0.5f) / kStrata, (b + 0.5f) / kStrata});
                    const Vec3f wi = reflect(wo, m);
                    if (wi.z <= 0) continue;
                    sum += fresnel_dielectric(dot(wo, m), eta_) * ggx_.g2(wo, wi) / ggx_.g1(wo);
                }
            }
            reflectance_table_[i] = float(sum / (kStrata * kStrata));
        }
    }
    // 2 * integral of T(mu) mu dmu with mu = t^2, i.e. integral of 4 t^3 T(t^2) dt, by Simpson's rule with
    // eight intervals per table interval (T is smooth within each).
    constexpr int intervals = 8 * (kTableSize - 1);
    const auto integrand = [this](double t) { return 4.0 * t * t * t * transmittance(float(t * t)); };
    double sum = integrand(0.0) + integrand(1.0);
    for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(double(i) / intervals);
    mean_transmittance_ = float(sum / (3.0 * intervals));
    internal_diffuse_reflectance_ = 1.0f - (1.0f - diffuse_fresnel_reflectance(eta_)) / (eta_ * eta_);
}

float DielectricCoating::reflectance(float mu) const {
    return smooth_ ? fresnel_dielectric(mu, eta_) : tabulated_reflectance(mu);
}

float DielectricCoating::tabulated_reflectance(float mu) const {
    // Linear in t = sqrt(mu), matching the table's spacing.
    const float x = std::sqrt(std::clamp(mu, 0.0f, 1.0f)) * (kTableSize - 1);
    const int i = std::min(int(x), kTableSize - 2);
    const float f = x - i;
    return (1.0f - f) * reflectance_table_[i] + f * reflectance_table_[i + 1];
}

float DielectricCoating::reflection(const Vec3f& wo, const Vec3f& wi) const {
    if (smooth_) return 0;
    const std::optional<Vec3f> m = microfacet_normal(wo, wi, 1.0f);
    if (!m) return 0;
    return fresnel_dielectric(dot(wo, *m), eta_) * microfacet_reflection(ggx_, wo, wi, *m);
}

float DielectricCoating::reflection_pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (smooth_) return 0;
    const std::optional<Vec3f> m = microfacet_normal(wo, wi, 1.0f);
    return m ? microfacet_reflection_pdf(ggx_, wo, *m) : 0.0f;
}

Vec3f DielectricCoating::sample_reflection(const Vec3f& wo, std::array<float, 2> u) const {
    return reflect(wo, ggx_.sample_visible_normal(wo, u));
}

}  // namespace isotrace
