#include "renderer/bsdf/charlie_sheen.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "renderer/bsdf/albedo_grid.h"
#include "renderer/bsdf/shading_frame.h"

namespace isotrace {
namespace {

// Nodes (albedo_grid.h): mu, and roughness over [kMinSheenRoughness, 1].
constexpr int kMuNodes = 32;
constexpr int kRoughnessNodes = 16;

float node_roughness(int j) {
    return kMinSheenRoughness + (1.0f - kMinSheenRoughness) * float(j) / (kRoughnessNodes - 1);
}

std::vector<float> build_table() {
    std::vector<float> albedo(std::size_t(kRoughnessNodes) * kMuNodes);
    for (int j = 0; j < kRoughnessNodes; ++j) {
        const float r = node_roughness(j);
        const CharlieSheen sheen(r);
        // The share of D(m) m.z with sin theta_m <= s is s^(2 + 1/a).
        const double exponent = 2.0 + 1.0 / (double(r) * r);
        const MicrofacetCdf cdf{[exponent](double theta) { return std::pow(std::sin(theta), exponent); },
                                [exponent](double u) { return std::asin(std::pow(u, 1.0 / exponent)); }};
        for (int i = 0; i < kMuNodes; ++i) {
            const float mu = albedo_grid_mu(i, kMuNodes);
            const Vec3f wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
            // E = integral of G2 (wo.m) / (mu_o m.z) D(m) m.z dm: f cos dwi with dwi = 4 (wo.m) dm.
            double sum = 0;
            visit_reflecting_normals(wo, cdf, [&](const Vec3f& m, double weight) {
                const Vec3f wi = reflect(wo, m);
                if (wi.z > 0) sum += weight * sheen.g2(wo, wi) * dot(wo, m) / (mu * m.z);
            });
            albedo[std::size_t(j) * kMuNodes + i] = float(sum);
        }
    }
    return albedo;
}

const std::vector<float>& table() {
    static const std::vector<float> built = build_table();
    return built;
}

}  // namespace

CharlieSheen::CharlieSheen(float roughness) {
    const float r = roughness > kMinSheenRoughness ? std::min(roughness, 1.0f) : kMinSheenRoughness;  // NaN too
    const float alpha = r * r;
    inverse_alpha_ = 1.0f / alpha;
    // Estevez and Kulla's table 1: the coefficients at a = 0 and a = 1, blended by (1 - a)^2.
    constexpr float smooth[5] = {25.3245f, 3.32435f, 0.16801f, -1.27393f, -4.85967f};
    constexpr float rough[5] = {21.5473f, 3.82987f, 0.19823f, -1.97760f, -4.32054f};
    const float t = (1.0f - alpha) * (1.0f - alpha);
    for (int k = 0; k < 5; ++k) fit_[k] = lerp(rough[k], smooth[k], t);
    roughness_coordinate_ = (r - kMinSheenRoughness) / (1.0f - kMinSheenRoughness) * (kRoughnessNodes - 1);
}

float CharlieSheen::d(const Vec3f& m) const {
    const float sin2 = std::max(0.0f, 1.0f - m.z * m.z);
    return (2.0f + inverse_alpha_) * std::pow(sin2, 0.5f * inverse_alpha_) * (0.5f * std::numbers::inv_pi_v<float>);
}

float CharlieSheen::lambda(float cosine) const {
    // Unit directions carried into the shading frame may come out with |z| a rounding above 1, where the fit's
    // 1 - mu would be negative (a NaN power).
    const float mu = std::clamp(std::abs(cosine), 0.0f, 1.0f);
    const auto l = [this](float x) {
        return fit_[0] / (1.0f + fit_[1] * std::pow(x, fit_[2])) + fit_[3] * x + fit_[4];
    };
    return mu < 0.5f ? std::exp(l(mu)) : std::exp(2.0f * l(0.5f) - l(1.0f - mu));
}

float CharlieSheen::eval(const Vec3f& wo, const Vec3f& wi) const {
    const Vec3f sum = wo + wi;
    const float length2 = dot(sum, sum);
    if (!(length2 > 0)) return 0;
    const Vec3f h = sum / std::sqrt(length2);
    return d(h) * g2(wo, wi) / (4.0f * wo.z * wi.z);
}

float CharlieSheen::g2(const Vec3f& wo, const Vec3f& wi) const {
    return 1.0f / (1.0f + lambda(wo.z) + lambda(wi.z));
}

float CharlieSheen::albedo(float mu) const {
    const AlbedoGridCell m = albedo_grid_mu_cell(mu, kMuNodes);
    const AlbedoGridCell r = albedo_grid_cell(roughness_coordinate_, kRoughnessNodes);
    const float* lower = &table()[std::size_t(r.node) * kMuNodes + m.node];
    const float* upper = lower + kMuNodes;
    return lerp(lerp(lower[0], lower[1], m.fraction), lerp(upper[0], upper[1], m.fraction), r.fraction);
}

}  // namespace isotrace
