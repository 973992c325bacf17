#include "renderer/image_compare/z_test.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "renderer/image_compare/pixel_error.h"

namespace isotrace {
namespace {

constexpr std::size_t kListedFailures = 12;

// Per pixel and channel: the difference of the means, the variance of that difference, and its weight in block
// sums, 1 / (|reference| + 0.01), so that a block sums relative differences (z_test.h says why).
struct Differences {
    std::vector<double> difference, variance, weight;
};

Differences pixel_differences(const ZTestInput& input, const ZTestSettings& settings) {
    const std::size_t pixels = input.test.pixel_count();
    const bool test_variance = input.test_variance.pixel_count() > 0;
    Differences d;
    d.difference.resize(3 * pixels);
    d.variance.resize(3 * pixels);
    d.weight.resize(3 * pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        const double n_reference = input.reference_samples[i], n_test = input.test_samples[i];
        if (!(n_reference >= 1) || !(n_test >= 1))
            throw std::invalid_argument("z-test: pixel " + std::to_string(i % std::size_t(input.test.width)) + "," +
                                        std::to_string(i / std::size_t(input.test.width)) +
                                        " has a sample count below 1");
        for (std::size_t k = 3 * i; k < 3 * i + 3; ++k) {
            const double reference_spread =
                std::max(double(input.reference_variance.values[k]) * n_reference, settings.variance_floor);
            const double test_spread =
                test_variance ? std::max(double(input.test_variance.values[k]) * n_test, reference_spread)
                              : reference_spread;
            d.difference[k] = double(input.test.values[k]) - double(input.reference_mean.values[k]);
            d.variance[k] = test_spread / n_test + reference_spread / n_reference;
            d.weight[k] = 1 / (std::abs(double(input.reference_mean.values[k])) + kRelativeMseEpsilon);
        }
    }
    return d;
}

// The block edges tested: the settings' edges up to the first that covers the image, then the whole image.
std::vector<int> level_edges(const ZTestSettings& settings, int width, int height) {
    const int whole = std::max(width, height);
    std::vector<int> edges = {1};
    if (settings.block_edges.empty()) return edges;
    for (int edge : settings.block_edges) {
        if (edge <= edges.back()) continue;
        edges.push_back(std::min(edge, whole));
        if (edge >= whole) return edges;
    }
    if (edges.back() < whole) edges.push_back(whole);
    return edges;
}

// Tests every edge x edge block of one level; failing tests go to `failures`.
ZTestLevel test_level(const ZTestInput& input, const Differences& d, int edge, double significance,
                      std::vector<ZTestFailure>& failures, std::vector<float>* failed_per_pixel) {
    const int width = input.test.width, height = input.test.height;
    ZTestLevel level;
    level.edge = edge;
    const std::int64_t blocks = std::int64_t((width + edge - 1) / edge) * ((height + edge - 1) / edge);
    level.tests = 3 * blocks;
    // 1 - (1 - s)^(1/N) without cancellation for large N.
    level.alpha = -std::expm1(std::log1p(-significance) / double(level.tests));
    for (int y0 = 0; y0 < height; y0 += edge) {
        for (int x0 = 0; x0 < width; x0 += edge) {
            for (int c = 0; c < 3; ++c) {
                double weighted = 0, variance = 0, difference = 0, reference = 0;
                int count = 0;
                for (int y = y0; y < std::min(y0 + edge, height); ++y) {
                    for (int x = x0; x < std::min(x0 + edge, width); ++x) {
                        const std::size_t k = 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x)) + std::size_t(c);
                        weighted += d.weight[k] * d.difference[k];
                        variance += d.weight[k] * d.weight[k] * d.variance[k];
                        difference += d.difference[k];
                        reference += input.reference_mean.values[k];
                        ++count;
                    }
                }
                const double z = weighted / std::sqrt(variance);
                const double p = std::isnan(z) ? 0.0 : std::erfc(std::abs(z) / std::sqrt(2.0));
                level.min_p_value = std::min(level.min_p_value, p);
                if (p > level.alpha) continue;
                ++level.failed;
                if (failed_per_pixel) (*failed_per_pixel)[std::size_t(y0) * std::size_t(width) + std::size_t(x0)] += 1;
                failures.push_back({edge, x0, y0, c, (reference + difference) / count, reference / count, z, p});
            }
        }
    }
    level.pass_fraction = double(level.tests - level.failed) / double(level.tests);
    return level;
}

}  // namespace

ZTestResult z_test(const ZTestInput& input, const ZTestSettings& settings) {
    require_same_size(input.reference_mean, input.test);
    require_same_size(input.reference_mean, input.reference_variance);
    if (input.test_variance.pixel_count() > 0) require_same_size(input.reference_mean, input.test_variance);
    const std::size_t pixels = input.test.pixel_count();
    if (input.reference_samples.size() != pixels || input.test_samples.size() != pixels)
        throw std::invalid_argument("z-test: one sample count per pixel is needed for both images");

    const Differences d = pixel_differences(input, settings);
    const std::vector<int> edges = level_edges(settings, input.test.width, input.test.height);
    ZTestResult result;
    result.failed_per_pixel.assign(pixels, 0.0f);
    std::vector<ZTestFailure> failures;
    result.passed = true;
    for (int edge : edges) {
        ZTestLevel level = test_level(input, d, edge, settings.significance / double(edges.size()), failures,
                                      edge == 1 ? &result.failed_per_pixel : nullptr);
        level.passed = level.pass_fraction >= settings.required_pass_fraction;
        result.passed = result.passed && level.passed;
        result.levels.push_back(level);
    }
    const std::size_t listed = std::min(failures.size(), kListedFailures);
    std::partial_sort(failures.begin(), failures.begin() + std::ptrdiff_t(listed), failures.end(),
                      [](const ZTestFailure& a, const ZTestFailure& b) {
                          // p underflows to 0 far out: the larger |z| is then the worse
                          return a.p_value != b.p_value ? a.p_value < b.p_value : std::abs(a.z) > std::abs(b.z);
                      });
    result.worst.assign(failures.begin(), failures.begin() + std::ptrdiff_t(listed));
    return result;
}

}  // namespace isotrace
