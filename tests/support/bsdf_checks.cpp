#include "tests/support/bsdf_checks.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include "renderer/sampling/independent_sampler.h"

namespace isotrace::test_support {
namespace {

constexpr double kPi = std::numbers::pi;

// (cos theta, phi) preserves area, so densities per solid angle are densities on this grid. 40 x 80 cells
// resolve lobes down to alpha ~ 0.05 without making the quadrature slow.
const Grid2D kSphereGrid{-1, 1, 0, 2 * kPi, 40, 80};

// The grid is half-open, [-1, 1) x [0, 2 pi): a float normal is often exactly (0, 0, 1), and a tiny negative
// azimuth plus 2 pi rounds to 2 pi, so both edges are folded inside.
Point2 to_cos_theta_phi(const Vec3f& w) {
    const double z = std::min(double(w.z), std::nextafter(1.0, 0.0));
    double phi = std::atan2(double(w.y), double(w.x));
    if (phi < 0) phi += 2 * kPi;
    return {z, phi < 2 * kPi ? phi : 0.0};
}

Vec3f from_cos_theta_phi(double z, double phi) {
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    return Vec3f(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
}

constexpr Point2 kOutside{std::numeric_limits<double>::quiet_NaN(), 0};

// The BSDFs compute in float, so their densities are only smooth to a relative 1e-7: an absolute tolerance
// alone (as in expected_counts_2d) can be unreachable inside a narrow lobe and drives every subdivision to its
// depth limit. Hence a relative tolerance as well, far above float rounding.
constexpr double kRelativeTolerance = 1e-5;
constexpr int kMaxDepth = 16;
// The first level is always split (each interval gets at least 9 nodes), so that a lobe's sliver between
// the nodes of a coarse rule cannot pass for zero.
constexpr int kMinDepth = 1;

// Adaptive Simpson on [a, b] given f at a, the midpoint and b, with Richardson extrapolation.
double adaptive_simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm, double fb,
                        double whole, double tolerance, int depth) {
    const double m = 0.5 * (a + b);
    const double left_mid = f(0.5 * (a + m)), right_mid = f(0.5 * (m + b));
    const double left = (m - a) / 6 * (fa + 4 * left_mid + fm);
    const double right = (b - m) / 6 * (fm + 4 * right_mid + fb);
    const double refined = left + right, error = refined - whole;
    const bool converged = std::abs(error) <= std::max(15 * tolerance, kRelativeTolerance * std::abs(refined));
    if (depth == 0 || (converged && depth <= kMaxDepth - kMinDepth)) return refined + error / 15;
    return adaptive_simpson(f, a, m, fa, left_mid, fm, left, 0.5 * tolerance, depth - 1) +
           adaptive_simpson(f, m, b, fm, right_mid, fb, right, 0.5 * tolerance, depth - 1);
}

double integrate(const std::function<double(double)>& f, double a, double b, double tolerance) {
    const double fa = f(a), fm = f(0.5 * (a + b)), fb = f(b);
    return adaptive_simpson(f, a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), tolerance, kMaxDepth);
}

// Integrals of f over each cell of kSphereGrid (row-major, as histogram_2d), each to `tolerance` absolute.
std::vector<double> cell_integrals(const std::function<double(const Vec3f&)>& f, double tolerance) {
    const auto density = [&](double z, double phi) { return f(from_cos_theta_phi(z, phi)); };
    const Grid2D& g = kSphereGrid;
    const double width = (g.x_max - g.x_min) / g.columns, height = (g.y_max - g.y_min) / g.rows;
    std::vector<double> cells;
    cells.reserve(std::size_t(g.columns) * g.rows);
    // Nested 1D integration refines only along the axis that needs it (a lobe at a pole is narrow in cos theta
    // but smooth in phi).
    for (int row = 0; row < g.rows; ++row) {
        const double y0 = g.y_min + row * height;
        for (int column = 0; column < g.columns; ++column) {
            const double x0 = g.x_min + column * width;
            const auto inner = [&](double x) {
                return integrate([&](double y) { return density(x, y); }, y0, y0 + height, tolerance / width);
            };
            cells.push_back(integrate(inner, x0, x0 + width, tolerance));
        }
    }
    return cells;
}

}  // namespace

Vec3f direction_from_degrees(double theta, double phi) {
    const double t = theta * kPi / 180, p = phi * kPi / 180;
    return Vec3f(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t)));
}

BsdfRandom bsdf_random(std::size_t i) {
    static const IndependentSampler sampler(7411);
    const PixelSampleKey key{static_cast<uint32_t>(i), static_cast<uint32_t>(i >> 32), 0};
    return {sampler.sample(key, 0), {sampler.sample(key, 1), sampler.sample(key, 2)}};
}

SamplingFit direction_sampling_fit(const std::function<std::optional<Vec3f>(const BsdfRandom&)>& sample,
                                   std::size_t sample_count, const std::function<double(const Vec3f&)>& pdf) {
    Histogram2D histogram = histogram_2d(kSphereGrid, sample_count, [&](std::size_t i) {
        const std::optional<Vec3f> w = sample(bsdf_random(i));
        return w ? to_cos_theta_phi(*w) : kOutside;
    });
    // Cell expectations to a tenth of a sample, far below the chi-square's resolution.
    std::vector<double> expected = cell_integrals(pdf, 0.1 / double(sample_count));
    const double n = double(sample_count);
    SamplingFit fit;
    fit.pdf_integral = std::accumulate(expected.begin(), expected.end(), 0.0);
    for (double& e : expected) e *= n;
    // As in chi_square_test_2d: the outside bin expects the unclaimed mass, and a residual below a hundredth
    // of a sample is quadrature error, so any sample there then fails the test outright.
    const double expected_outside = n * (1.0 - fit.pdf_integral);
    histogram.counts.push_back(histogram.outside);
    expected.push_back(expected_outside < 0.01 ? 0.0 : expected_outside);
    fit.chi_square = chi_square_test(histogram.counts, expected);
    return fit;
}

SamplingFit sampling_fit(const SurfaceBsdf& bsdf, const Vec3f& wo, std::size_t sample_count,
                         const std::function<double(const Vec3f&)>& pdf) {
    const auto sample = [&](const BsdfRandom& r) -> std::optional<Vec3f> {
        const std::optional<BsdfSample> s = bsdf.sample(wo, r.u_lobe, r.u);
        if (!s || s->is_delta) return std::nullopt;
        return s->wi;
    };
    return direction_sampling_fit(sample, sample_count, pdf);
}

SamplingFit sampling_fit(const SurfaceBsdf& bsdf, const Vec3f& wo, std::size_t sample_count) {
    return sampling_fit(bsdf, wo, sample_count, [&](const Vec3f& wi) { return double(bsdf.pdf(wo, wi)); });
}

double sphere_integral(const std::function<double(const Vec3f&)>& f) {
    const std::vector<double> cells = cell_integrals(f, 1e-7);
    return std::accumulate(cells.begin(), cells.end(), 0.0);
}

double pdf_integral(const SurfaceBsdf& bsdf, const Vec3f& wo) {
    return sphere_integral([&](const Vec3f& wi) { return double(bsdf.pdf(wo, wi)); });
}

AlbedoEstimate estimate_albedo(const SurfaceBsdf& bsdf, const Vec3f& wo, std::size_t sample_count, TransportMode mode) {
    double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
    for (std::size_t i = 0; i < sample_count; ++i) {
        const BsdfRandom r = bsdf_random(i);
        const std::optional<BsdfSample> s = bsdf.sample(wo, r.u_lobe, r.u, mode);
        if (!s) continue;
        const double w[3] = {s->weight.r, s->weight.g, s->weight.b};
        for (int c = 0; c < 3; ++c) {
            sum[c] += w[c];
            sum2[c] += w[c] * w[c];
        }
    }
    const double n = double(sample_count);
    double mean[3], error[3];
    for (int c = 0; c < 3; ++c) {
        mean[c] = sum[c] / n;
        error[c] = std::sqrt(std::max(0.0, sum2[c] / n - mean[c] * mean[c]) / n);
    }
    return {Rgb(float(mean[0]), float(mean[1]), float(mean[2])), Rgb(float(error[0]), float(error[1]), float(error[2]))};
}

std::size_t count_bad_samples(const SurfaceBsdf& bsdf, const Vec3f& wo, std::size_t sample_count, TransportMode mode) {
    const auto close = [](float a, float b) { return std::abs(a - b) <= 1e-4f * std::max(std::abs(a), std::abs(b)) + 1e-12f; };
    std::size_t bad = 0;
    for (std::size_t i = 0; i < sample_count; ++i) {
        const BsdfRandom r = bsdf_random(i);
        const std::optional<BsdfSample> s = bsdf.sample(wo, r.u_lobe, r.u, mode);
        if (!s) continue;
        const bool finite = s->weight.is_finite() && is_finite(s->wi) && std::isfinite(s->pdf) && s->pdf > 0 &&
                            std::abs(length(s->wi) - 1.0f) < 1e-4f;
        if (!finite) {
            ++bad;
            continue;
        }
        if (s->is_delta) continue;
        const Rgb expected = bsdf.eval(wo, s->wi, mode) * (std::abs(s->wi.z) / s->pdf);
        const bool consistent = close(s->pdf, bsdf.pdf(wo, s->wi)) && close(s->weight.r, expected.r) &&
                                close(s->weight.g, expected.g) && close(s->weight.b, expected.b);
        if (!consistent) ++bad;
    }
    return bad;
}

std::string roughness_and_view_name(const testing::TestParamInfo<std::tuple<Roughness, double>>& info) {
    const auto& [roughness, theta] = info.param;
    return "alpha" + std::to_string(int(roughness.alpha_x * 100)) + "x" + std::to_string(int(roughness.alpha_y * 100)) +
           "_theta" + std::to_string(int(theta));
}

}  // namespace isotrace::test_support
