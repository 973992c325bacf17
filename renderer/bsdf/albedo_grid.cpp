#include "renderer/bsdf/albedo_grid.h"

#include <array>
#include <numbers>

namespace isotrace {
namespace {

constexpr int kNodes = 16;

// Newton's method on the Legendre polynomial.
GaussLegendre build_gauss_legendre() {
    constexpr int n = kNodes;
    GaussLegendre rule;
    for (int i = 0; i < n; ++i) {
        double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), derivative = 1;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p = 1, previous = 0;
            for (int j = 0; j < n; ++j) {
                const double older = previous;
                previous = p;
                p = ((2 * j + 1) * z * previous - j * older) / (j + 1);
            }
            derivative = n * (z * p - previous) / (z * z - 1);
            const double step = p / derivative;
            z -= step;
            if (std::abs(step) < 1e-15) break;
        }
        rule.x[i] = 0.5 * (1 - z);
        rule.w[i] = 1.0 / ((1 - z * z) * derivative * derivative);
    }
    return rule;
}

}  // namespace

const GaussLegendre& gauss_legendre() {
    static const GaussLegendre rule = build_gauss_legendre();
    return rule;
}

void visit_reflecting_normals(const Vec3f& wo, const MicrofacetCdf& cdf,
                              const std::function<void(const Vec3f& m, double weight)>& visit) {
    const GaussLegendre& rule = gauss_legendre();
    constexpr double kPi = std::numbers::pi;
    const double sin_o = std::sqrt(std::max(0.0, 1.0 - double(wo.z) * wo.z));
    for (int half = 0; half < 2; ++half) {
        for (int j = 0; j < kNodes; ++j) {
            const double phi = (half + rule.x[j]) * kPi / 2;
            // The weight of phi as a share of [0, pi], which stands for the whole circle by symmetry.
            const double phi_weight = rule.w[j] / 2;
            const double delta = std::atan2(sin_o * std::cos(phi), double(wo.z));
            const double u_max = cdf.u_of_theta(0.5 * (delta + kPi / 2));
            // In s = sqrt(1 - u): integrands of the form (wo.m) / m.z grow as 1 / sqrt(1 - u) towards grazing
            // normals, which s turns into a smooth function (du = 2 s ds).
            const double s_min = std::sqrt(std::max(0.0, 1.0 - u_max));
            for (int i = 0; i < kNodes; ++i) {
                const double s = s_min + (1.0 - s_min) * rule.x[i];
                const double theta = cdf.theta_of_u(1.0 - s * s);
                const double sin_theta = std::sin(theta);
                const Vec3f m(float(sin_theta * std::cos(phi)), float(sin_theta * std::sin(phi)),
                              float(std::cos(theta)));
                visit(m, phi_weight * (1.0 - s_min) * 2.0 * s * rule.w[i]);
            }
        }
    }
}

}  // namespace isotrace
