#pragma once
// Statistical checks shared by the BSDF tests: goodness of fit of sample() against pdf(), the pdf's total
// mass, and Monte Carlo albedo (white furnace) estimates.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "renderer/bsdf/surface_bsdf.h"
#include "tests/support/chi_square.h"

namespace isotrace::test_support {

// The unit direction at polar angle theta (from +z) and azimuth phi, in degrees.
Vec3f direction_from_degrees(double theta, double phi = 0);

// The roughness grid and viewing directions the microfacet sampling tests share.
struct Roughness {
    float alpha_x, alpha_y;
};
inline constexpr Roughness kRoughnesses[] = {{0.05f, 0.05f}, {0.3f, 0.3f}, {0.8f, 0.8f}, {0.1f, 0.6f}};
// wo at polar angle theta (degrees from the normal) and azimuth 30 degrees.
inline Vec3f view_at(double theta) { return direction_from_degrees(theta, 30); }
// Name of a test parameterised by (roughness, view angle), such as "alpha10x60_theta85".
std::string roughness_and_view_name(const testing::TestParamInfo<std::tuple<Roughness, double>>& info);

// The random numbers of the i-th BSDF sample: independent and deterministic (the chi-square test assumes
// independent samples).
struct BsdfRandom {
    float u_lobe;
    std::array<float, 2> u;
};
BsdfRandom bsdf_random(std::size_t i);

struct SamplingFit {
    ChiSquareResult chi_square;
    double pdf_integral = 0;  // integral of the claimed pdf over the sphere
};

// Histograms sample_count directions from bsdf.sample(wo, ...) over (cos theta, phi) of the whole sphere and
// tests them against `pdf` integrated over each cell. Delta samples and failed samples land outside the grid,
// where the expectation is the mass the pdf leaves unclaimed (1 - pdf_integral).
SamplingFit sampling_fit(const SurfaceBsdf& bsdf, const Vec3f& wo, std::size_t sample_count,
                         const std::function<double(const Vec3f&)>& pdf);
// The same against bsdf.pdf().
SamplingFit sampling_fit(const SurfaceBsdf& bsdf, const Vec3f& wo, std::size_t sample_count);

// Directions sampled by `sample` (empty = no direction) against `pdf`, as above; for samplers that are not
// BSDFs (microfacet normals).
SamplingFit direction_sampling_fit(const std::function<std::optional<Vec3f>(const BsdfRandom&)>& sample,
                                   std::size_t sample_count, const std::function<double(const Vec3f&)>& pdf);

// Integral of a function of direction over the unit sphere by adaptive quadrature (to a relative 1e-5 or an
// absolute 1e-7 per grid cell, so within 3e-4 for a density).
double sphere_integral(const std::function<double(const Vec3f&)>& f);
// Integral of bsdf.pdf(wo, .) over the sphere.
double pdf_integral(const SurfaceBsdf& bsdf, const Vec3f& wo);

struct AlbedoEstimate {
    Rgb mean;             // integral of f |cos| over the sphere, delta lobes included, in `mode`
    Rgb standard_error;   // of the mean
};
// Monte Carlo estimate from the weights of sample_count samples (the white furnace test).
AlbedoEstimate estimate_albedo(const SurfaceBsdf& bsdf, const Vec3f& wo, std::size_t sample_count,
                               TransportMode mode = TransportMode::Radiance);

// Number of sample_count samples from wo that are non-finite, or non-delta yet disagree with eval() and pdf()
// (weight != eval |cos| / pdf or pdf != pdf(), beyond float rounding).
std::size_t count_bad_samples(const SurfaceBsdf& bsdf, const Vec3f& wo, std::size_t sample_count,
                              TransportMode mode = TransportMode::Radiance);

}  // namespace isotrace::test_support
