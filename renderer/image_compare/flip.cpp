#include "renderer/math/median.h"
#include "renderer/image_compare/flip.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/image_compare/flip_colour.h"
#include "renderer/image_compare/separable_filter.h"

namespace isotrace {
namespace {

using flip::Colour;
constexpr double kPi = std::numbers::pi;

// ---- contrast sensitivity filters (paper section 4.1, eq. 2) ------------------------------------------------

// One term a sqrt(pi / b) exp(-pi^2 r^2 / b) of a channel's CSF, r in degrees.
struct CsfTerm {
    double a, b;
};
const std::vector<CsfTerm> kAchromatic = {{1.0, 0.0047}};
const std::vector<CsfTerm> kRedGreen = {{1.0, 0.0053}};
const std::vector<CsfTerm> kBlueYellow = {{34.1, 0.04}, {13.5, 0.025}};
constexpr double kWidestCsfB = 0.04;

// Filters a plane with a CSF: each Gaussian term is separable, and the 2-D kernel's normalisation (its sum over
// the square support) is the sum over terms of the coefficient times the square of the 1-D sum.
std::vector<float> csf_filter(const std::vector<float>& plane, int width, int height, const std::vector<CsfTerm>& terms,
                              double pixels_per_degree) {
    const int radius = int(std::ceil(3 * std::sqrt(kWidestCsfB / (2 * kPi * kPi)) * pixels_per_degree));
    const double step = 1 / pixels_per_degree;  // degrees per pixel
    std::vector<Kernel1d> kernels;
    std::vector<double> coefficients;
    double normalisation = 0;
    for (const CsfTerm& term : terms) {
        Kernel1d g(std::size_t(2 * radius + 1));
        double sum = 0;
        for (int k = -radius; k <= radius; ++k)
            sum += g[std::size_t(k + radius)] = std::exp(-kPi * kPi * (k * step) * (k * step) / term.b);
        const double c = term.a * std::sqrt(kPi / term.b);
        normalisation += c * sum * sum;
        kernels.push_back(std::move(g));
        coefficients.push_back(c);
    }
    std::vector<float> result(plane.size(), 0.0f);
    for (std::size_t t = 0; t < kernels.size(); ++t) {
        Kernel1d scaled = kernels[t];
        for (double& w : scaled) w *= coefficients[t] / normalisation;
        const std::vector<float> part = filter_separable(plane, width, height, scaled, kernels[t]);
        for (std::size_t i = 0; i < result.size(); ++i) result[i] += part[i];
    }
    return result;
}

// ---- feature detection (paper section 4.2) --------------------------------------------------------------------

// Derivative-of-Gaussian kernels with standard deviation 0.5 * 0.082 degrees (half the peak-to-trough width of
// the human edge detector), positive weights scaled to sum to 1 and negative ones to -1.
struct FeatureKernels {
    Kernel1d edge, point, smooth;  // smooth: the Gaussian across the derivative, summing to 1
};

FeatureKernels feature_kernels(double pixels_per_degree) {
    const double sd = 0.5 * 0.082 * pixels_per_degree;
    const int radius = int(std::ceil(3 * sd));
    FeatureKernels k;
    for (int i = -radius; i <= radius; ++i) {
        const double g = std::exp(-(i * i) / (2 * sd * sd));
        k.smooth.push_back(g);
        k.edge.push_back(-i * g);
        k.point.push_back((i * i / (sd * sd) - 1) * g);
    }
    const auto balance = [](Kernel1d& kernel) {
        double positive = 0, negative = 0;
        for (double w : kernel) (w > 0 ? positive : negative) += w;
        for (double& w : kernel) w /= w > 0 ? positive : -negative;
    };
    balance(k.edge);
    balance(k.point);
    double sum = 0;
    for (double w : k.smooth) sum += w;
    for (double& w : k.smooth) w /= sum;
    return k;
}

// |(d/dx, d/dy)| of a plane under a 1-D derivative kernel and the cross smoothing.
std::vector<float> feature_magnitude(const std::vector<float>& y, int width, int height, const Kernel1d& derivative,
                                     const Kernel1d& smooth) {
    const std::vector<float> dx = filter_separable(y, width, height, derivative, smooth);
    const std::vector<float> dy = filter_separable(y, width, height, smooth, derivative);
    std::vector<float> magnitude(y.size());
    for (std::size_t i = 0; i < y.size(); ++i) magnitude[i] = std::hypot(dx[i], dy[i]);
    return magnitude;
}

// ---- one image through the pipeline ----------------------------------------------------------------------------

struct Prepared {
    std::vector<Colour> hunt_lab;      // CSF-filtered, clamped, Hunt-adjusted L*a*b*
    std::vector<float> edges, points;  // feature magnitudes of the luminance
};

Prepared prepare(const RgbImage& linear, double pixels_per_degree, const FeatureKernels& kernels) {
    const std::size_t n = linear.pixel_count();
    std::vector<float> opponent[3];
    for (auto& plane : opponent) plane.resize(n);
    std::vector<float> luminance(n);
    for (std::size_t i = 0; i < n; ++i) {
        const float* p = linear.values.data() + 3 * i;
        const Colour c = flip::xyz_to_ycxcz(flip::linear_rgb_to_xyz(
            {std::clamp(double(p[0]), 0.0, 1.0), std::clamp(double(p[1]), 0.0, 1.0), std::clamp(double(p[2]), 0.0, 1.0)}));
        for (int k = 0; k < 3; ++k) opponent[k][i] = float(c[std::size_t(k)]);
        luminance[i] = float((c[0] + 16) / 116);  // Y relative to white, in [0, 1]
    }
    const int w = linear.width, h = linear.height;
    const std::vector<float> filtered[3] = {csf_filter(opponent[0], w, h, kAchromatic, pixels_per_degree),
                                            csf_filter(opponent[1], w, h, kRedGreen, pixels_per_degree),
                                            csf_filter(opponent[2], w, h, kBlueYellow, pixels_per_degree)};
    Prepared prepared;
    prepared.hunt_lab.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        Colour rgb = flip::xyz_to_linear_rgb(flip::ycxcz_to_xyz({filtered[0][i], filtered[1][i], filtered[2][i]}));
        for (double& v : rgb) v = std::clamp(v, 0.0, 1.0);
        prepared.hunt_lab[i] = flip::hunt_adjust(flip::xyz_to_lab(flip::linear_rgb_to_xyz(rgb)));
    }
    prepared.edges = feature_magnitude(luminance, w, h, kernels.edge, kernels.smooth);
    prepared.points = feature_magnitude(luminance, w, h, kernels.point, kernels.smooth);
    return prepared;
}

// Maps HyAB^0.7 to [0, 1]: [0, 0.4 cmax) linearly onto [0, 0.95), the rest onto [0.95, 1].
double redistribute(double power_distance, double cmax) {
    constexpr double pc = 0.4, pt = 0.95;
    if (power_distance < pc * cmax) return pt / (pc * cmax) * power_distance;
    return pt + (power_distance - pc * cmax) / (cmax - pc * cmax) * (1 - pt);
}

constexpr double kColourExponent = 0.7, kFeatureExponent = 0.5;

// The largest colour difference: Hunt-adjusted green against blue, to the colour exponent.
double max_colour_distance() {
    const auto hunt = [](const Colour& rgb) { return flip::hunt_adjust(flip::xyz_to_lab(flip::linear_rgb_to_xyz(rgb))); };
    return std::pow(flip::hyab(hunt({0, 1, 0}), hunt({0, 0, 1})), kColourExponent);
}

// ACES fit coefficients: (k0 x^2 + k1 x) / (k3 x^2 + k4 x + k5), the 0.6 pre-exposure folded in.
constexpr double k0 = 0.6 * 0.6 * 2.51, k1 = 0.6 * 0.03, k3 = 0.6 * 0.6 * 2.43, k4 = 0.6 * 0.59, k5 = 0.14;

// The x the tone mapper maps to t (the positive root of the quadratic).
double aces_inverse(double t) {
    const double c0 = (k1 - k4 * t) / (k0 - k3 * t), c1 = -k5 * t / (k0 - k3 * t);
    return -0.5 * c0 + std::sqrt(0.25 * c0 * c0 - c1);
}

}  // namespace

FlipMaps ldr_flip_maps(const RgbImage& reference_linear, const RgbImage& test_linear, double pixels_per_degree) {
    require_same_size(reference_linear, test_linear);
    const FeatureKernels kernels = feature_kernels(pixels_per_degree);
    const Prepared reference = prepare(reference_linear, pixels_per_degree, kernels);
    const Prepared test = prepare(test_linear, pixels_per_degree, kernels);
    const double cmax = max_colour_distance();
    const std::size_t n = reference_linear.pixel_count();
    FlipMaps maps;
    maps.colour_error.resize(n);
    maps.feature_error.resize(n);
    maps.error.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double colour =
            redistribute(std::pow(flip::hyab(reference.hunt_lab[i], test.hunt_lab[i]), kColourExponent), cmax);
        const double feature_difference = std::max(std::abs(double(reference.edges[i]) - double(test.edges[i])),
                                                   std::abs(double(reference.points[i]) - double(test.points[i])));
        const double feature = std::pow(feature_difference / std::numbers::sqrt2, kFeatureExponent);
        maps.colour_error[i] = float(colour);
        maps.feature_error[i] = float(feature);
        maps.error[i] = float(std::pow(colour, 1 - feature));
    }
    return maps;
}

std::vector<float> ldr_flip(const RgbImage& reference_srgb, const RgbImage& test_srgb, double pixels_per_degree) {
    const auto decode = [](RgbImage image) {
        for (float& v : image.values) v = float(flip::srgb_decode(std::clamp(double(v), 0.0, 1.0)));
        return image;
    };
    return ldr_flip_maps(decode(reference_srgb), decode(test_srgb), pixels_per_degree).error;
}

double aces_tone_map(double x) {
    x = std::max(x, 0.0);
    if (std::isinf(x)) return 1.0;
    return std::clamp((k0 * x * x + k1 * x) / (k3 * x * x + k4 * x + k5), 0.0, 1.0);
}

FlipExposures hdr_flip_exposures(const RgbImage& reference) {
    const std::vector<float> y = luminance_plane(reference);
    const double brightest = y.empty() ? 0.0 : *std::max_element(y.begin(), y.end());
    if (!(brightest > 0)) return {0, 0, 2};
    double middle = median(y);
    if (!(middle > 0)) {
        std::vector<float> positive;
        for (float v : y)
            if (v > 0) positive.push_back(v);
        middle = median(std::move(positive));
    }
    constexpr double t = 0.85;
    FlipExposures exposures;
    exposures.start = std::log2(aces_inverse(t) / brightest);
    exposures.stop = std::log2(aces_inverse(t) / middle);
    exposures.count = std::max(2, int(std::ceil(exposures.stop - exposures.start)));
    return exposures;
}

std::vector<float> hdr_flip(const RgbImage& reference, const RgbImage& test, double pixels_per_degree,
                            const FlipExposures& exposures) {
    require_same_size(reference, test);
    std::vector<float> worst(reference.pixel_count(), 0.0f);
    for (int i = 0; i < exposures.count; ++i) {
        const double scale = std::exp2(exposures.exposure(i));
        const auto tone_map = [scale](RgbImage image) {
            for (float& v : image.values) v = float(aces_tone_map(scale * double(v)));
            return image;
        };
        const std::vector<float> error = ldr_flip_maps(tone_map(reference), tone_map(test), pixels_per_degree).error;
        for (std::size_t p = 0; p < worst.size(); ++p) worst[p] = std::max(worst[p], error[p]);
    }
    return worst;
}

}  // namespace isotrace
