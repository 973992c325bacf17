#include "renderer/bsdf/ggx_albedo.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "renderer/bsdf/albedo_grid.h"
#include "renderer/bsdf/fresnel.h"
#include "renderer/bsdf/ggx.h"
#include "renderer/bsdf/shading_frame.h"

namespace isotrace {
namespace {

// Nodes (albedo_grid.h): mu and perceptual roughness, and anisotropy for the averages.
constexpr int kMuNodes = 32;
constexpr int kRoughnessNodes = 32;
constexpr int kAnisotropyNodes = 8;

using AlbedoPair = std::array<float, 2>;

// The two tables, E for F = 1 and for F = (1 - wo.m)^5, interleaved: [roughness][mu][table].
struct Table {
    std::vector<AlbedoPair> albedo;
    std::vector<AlbedoPair> average;  // [anisotropy][roughness]
};

// Both tables at (mu, roughness coordinate).
AlbedoPair tabulated(const Table& table, float mu, float roughness_coordinate) {
    const AlbedoGridCell m = albedo_grid_mu_cell(mu, kMuNodes);
    const AlbedoGridCell r = albedo_grid_cell(roughness_coordinate, kRoughnessNodes);
    const AlbedoPair* lower = &table.albedo[std::size_t(r.node) * kMuNodes + m.node];
    const AlbedoPair* upper = lower + kMuNodes;
    const auto at = [&](int k) {
        return lerp(lerp(lower[0][k], lower[1][k], m.fraction), lerp(upper[0][k], upper[1][k], m.fraction), r.fraction);
    };
    return {at(0), at(1)};
}

float roughness_coordinate_of(float alpha) {
    return std::min(std::sqrt(std::max(alpha, 0.0f)), 1.0f) * (kRoughnessNodes - 1);
}

// GgxAlbedo::albedo(w, .) of an anisotropic lobe: the larger of the values at the geometric mean roughness and
// at the one w projects.
AlbedoPair anisotropic_albedo(const Table& table, const Vec3f& w, float roughness_coordinate, float alpha_x2,
                              float alpha_y2) {
    AlbedoPair e = tabulated(table, w.z, roughness_coordinate);
    const float x2 = w.x * w.x, y2 = w.y * w.y;
    if (x2 + y2 > 0) {
        const float projected_alpha = std::sqrt((alpha_x2 * x2 + alpha_y2 * y2) / (x2 + y2));
        const AlbedoPair projected = tabulated(table, w.z, roughness_coordinate_of(projected_alpha));
        for (int k = 0; k < 2; ++k) e[k] = std::max(e[k], projected[k]);
    }
    return e;
}

// (1 / pi) integral of E mu over the hemisphere of an anisotropic lobe: E depends on phi through cos^2 phi, so
// a quarter circle stands for the whole; mu = t^2 as on the grid, Gauss-Legendre in t and the midpoint rule
// in phi.
AlbedoPair anisotropic_average(const Table& table, float roughness, float anisotropy) {
    const auto [alpha_x, alpha_y] = anisotropic_alphas(roughness, anisotropy);
    const float coordinate = roughness_coordinate_of(alpha_x * alpha_y > 0 ? std::sqrt(alpha_x * alpha_y) : 0.0f);
    constexpr int kPhiNodes = 8;
    const GaussLegendre& rule = gauss_legendre();
    double sums[2] = {0, 0};
    for (int j = 0; j < kPhiNodes; ++j) {
        const double phi = (j + 0.5) / kPhiNodes * std::numbers::pi / 2;
        for (std::size_t i = 0; i < rule.x.size(); ++i) {
            const double t = rule.x[i], mu = t * t, sin_theta = std::sqrt(1 - mu * mu);
            const Vec3f w(float(sin_theta * std::cos(phi)), float(sin_theta * std::sin(phi)), float(mu));
            const AlbedoPair e = anisotropic_albedo(table, w, coordinate, alpha_x * alpha_x, alpha_y * alpha_y);
            const double weight = rule.w[i] * 4 * t * t * t / kPhiNodes;
            for (int k = 0; k < 2; ++k) sums[k] += weight * e[k];
        }
    }
    return {float(sums[0]), float(sums[1])};
}

// 2 * integral of E(mu) mu dmu = integral of 4 t^3 E(t) dt over the interpolant, linear in t between nodes:
// exact, so that a layer normalised by 1 - average reflects all it receives when the lobe above it is the table's.
float average_of(const AlbedoPair* row, int table) {
    const double h = 1.0 / (kMuNodes - 1);
    double sum = 0;
    for (int i = 0; i + 1 < kMuNodes; ++i) {
        const double t0 = i * h, t1 = (i + 1) * h;
        const double e0 = row[i][table], slope = (row[i + 1][table] - e0) / h;
        const double p4 = std::pow(t1, 4) - std::pow(t0, 4), p5 = std::pow(t1, 5) - std::pow(t0, 5);
        sum += e0 * p4 + slope * (0.8 * p5 - t0 * p4);
    }
    return float(sum);
}

Table build_table() {
    Table table;
    table.albedo.resize(std::size_t(kRoughnessNodes) * kMuNodes);
    for (int j = 0; j < kRoughnessNodes; ++j) {
        const float alpha = roughness_to_alpha(float(j) / (kRoughnessNodes - 1));
        const GgxDistribution ggx(alpha, alpha);
        const double alpha2 = double(ggx.alpha_x()) * ggx.alpha_x();
        const MicrofacetCdf cdf{
            [alpha2](double theta) {
                const double t = std::tan(theta), t2 = t * t;
                return t2 / (alpha2 + t2);
            },
            [alpha2](double u) { return std::atan(std::sqrt(alpha2 * u / (1 - u))); }};
        for (int i = 0; i < kMuNodes; ++i) {
            const float mu = albedo_grid_mu(i, kMuNodes);
            AlbedoPair& entry = table.albedo[std::size_t(j) * kMuNodes + i];
            if (j == 0) {
                entry = {1.0f, fresnel_schlick(mu, 0.0f)};
                continue;
            }
            // E = integral of F G2 (wo.m) / (mu_o m.z) D(m) m.z dm: f cos dwi with dwi = 4 (wo.m) dm.
            const Vec3f wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
            double sums[2] = {0, 0};
            visit_reflecting_normals(wo, cdf, [&](const Vec3f& m, double weight) {
                const Vec3f wi = reflect(wo, m);
                if (!(wi.z > 0)) return;
                const float cos_om = dot(wo, m);
                const double value = weight * ggx.g2(wo, wi) * cos_om / (mu * m.z);
                sums[0] += value;
                sums[1] += value * fresnel_schlick(cos_om, 0.0f);
            });
            entry = {float(sums[0]), float(sums[1])};
        }
    }
    table.average.resize(std::size_t(kAnisotropyNodes) * kRoughnessNodes);
    for (int j = 0; j < kRoughnessNodes; ++j) {
        const AlbedoPair* row = &table.albedo[std::size_t(j) * kMuNodes];
        table.average[j] = {average_of(row, 0), average_of(row, 1)};
        for (int k = 1; k < kAnisotropyNodes; ++k) {
            table.average[std::size_t(k) * kRoughnessNodes + j] = anisotropic_average(
                table, float(j) / (kRoughnessNodes - 1), float(k) / (kAnisotropyNodes - 1));
        }
    }
    return table;
}

const Table& table() {
    static const Table built = build_table();
    return built;
}

}  // namespace

std::array<float, 2> anisotropic_alphas(float roughness, float anisotropy) {
    const float alpha = roughness_to_alpha(roughness);
    const float k = std::sqrt(1.0f - 0.9f * anisotropy);
    return {alpha / k, alpha * k};
}

GgxAlbedo::GgxAlbedo(float roughness, float anisotropy)
    : roughness_coordinate_(roughness > 0 ? std::min(roughness, 1.0f) * (kRoughnessNodes - 1) : 0.0f),  // NaN too
      anisotropic_(roughness > 0 && anisotropy > 0) {
    if (anisotropic_) {
        const auto [alpha_x, alpha_y] = anisotropic_alphas(roughness, anisotropy);
        alpha_x2_ = alpha_x * alpha_x;
        alpha_y2_ = alpha_y * alpha_y;
    }
    const AlbedoGridCell r = albedo_grid_cell(roughness_coordinate_, kRoughnessNodes);
    const AlbedoGridCell a = albedo_grid_cell(anisotropy * (kAnisotropyNodes - 1), kAnisotropyNodes);
    const std::vector<AlbedoPair>& average = table().average;
    const auto at = [&](int k, int anisotropy_node) {
        const AlbedoPair* row = &average[std::size_t(anisotropy_node) * kRoughnessNodes + r.node];
        return lerp(row[0][k], row[1][k], r.fraction);
    };
    for (int k = 0; k < 2; ++k) average_[k] = lerp(at(k, a.node), at(k, a.node + 1), a.fraction);
}

float GgxAlbedo::albedo(float mu, float f0) const {
    if (roughness_coordinate_ == 0) return fresnel_schlick(mu, f0);
    const AlbedoPair e = tabulated(table(), mu, roughness_coordinate_);
    return f0 * e[0] + (1.0f - f0) * e[1];
}

float GgxAlbedo::albedo(const Vec3f& w, float f0) const {
    if (!anisotropic_) return albedo(w.z, f0);
    const AlbedoPair e = anisotropic_albedo(table(), w, roughness_coordinate_, alpha_x2_, alpha_y2_);
    return f0 * e[0] + (1.0f - f0) * e[1];
}

}  // namespace isotrace
