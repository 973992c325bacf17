#include "renderer/bsdf/fresnel.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace isotrace {
namespace {

using Complex = std::complex<double>;

// Both polarisations from Snell's law with a possibly complex relative IOR (double: the two amplitudes nearly
// cancel at grazing angles). For a real eta the principal square root keeps this equal to the real formula.
double unpolarised_reflectance(double cos_i, Complex eta) {
    const Complex sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
    const Complex cos_t = std::sqrt(1.0 - sin2_t);
    const Complex r_parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const Complex r_perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5 * (std::norm(r_parallel) + std::norm(r_perpendicular));
}

}  // namespace

float fresnel_dielectric(float cos_theta_i, float eta) {
    if (cos_theta_i < 0) {
        eta = 1.0f / eta;
        cos_theta_i = -cos_theta_i;
    }
    cos_theta_i = std::min(cos_theta_i, 1.0f);
    const float sin2_t = (1.0f - cos_theta_i * cos_theta_i) / (eta * eta);
    if (sin2_t >= 1.0f) return 1.0f;
    const float cos_t = std::sqrt(1.0f - sin2_t);
    const float r_parallel = (eta * cos_theta_i - cos_t) / (eta * cos_theta_i + cos_t);
    const float r_perpendicular = (cos_theta_i - eta * cos_t) / (cos_theta_i + eta * cos_t);
    return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

Rgb fresnel_conductor(float cos_theta_i, const ComplexIor& ior) {
    const double cos_i = std::clamp(double(cos_theta_i), 0.0, 1.0);
    const auto channel = [&](float eta, float k) { return float(unpolarised_reflectance(cos_i, Complex(eta, k))); };
    return {channel(ior.eta.r, ior.k.r), channel(ior.eta.g, ior.k.g), channel(ior.eta.b, ior.k.b)};
}

float fresnel_schlick(float cos_theta_i, float f0) {
    const float c = 1.0f - std::clamp(cos_theta_i, 0.0f, 1.0f), c2 = c * c;
    return f0 + (1.0f - f0) * (c2 * c2 * c);
}

Rgb fresnel_schlick(float cos_theta_i, const Rgb& f0) {
    return {fresnel_schlick(cos_theta_i, f0.r), fresnel_schlick(cos_theta_i, f0.g), fresnel_schlick(cos_theta_i, f0.b)};
}

Rgb average_fresnel_schlick(const Rgb& f0) {
    const auto channel = [](float f) { return f + (1.0f - f) / 21.0f; };
    return {channel(f0.r), channel(f0.g), channel(f0.b)};
}

float diffuse_fresnel_reflectance(float eta) {
    // Composite Simpson over mu in [0, 1]: the integrand is smooth from the front (no total internal
    // reflection), so 512 intervals leave only float rounding.
    constexpr int intervals = 512;
    const auto integrand = [eta](double mu) { return 2.0 * mu * fresnel_dielectric(float(mu), eta); };
    double sum = integrand(0.0) + integrand(1.0);
    for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(double(i) / intervals);
    return float(sum / (3.0 * intervals));
}

}  // namespace isotrace
