#include "renderer/sampling/independent_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

using test_support::chi_square_test;
using test_support::sidak_significance;

constexpr double kSignificance = 0.01;
constexpr int kStatisticalTests = 2;  // the two chi-square tests below

TEST(IndependentSampler, OneDimensionalHistogramIsUniform) {
    const IndependentSampler sampler(3);
    constexpr int bins = 100, samples = 200000;
    std::vector<double> observed(bins, 0), expected(bins, double(samples) / bins);
    for (uint32_t i = 0; i < samples; ++i) observed[static_cast<int>(sampler.sample({i % 500, i / 500, i}, 5) * bins)]++;
    EXPECT_GT(chi_square_test(observed, expected).p_value, sidak_significance(kSignificance, kStatisticalTests));
}

TEST(IndependentSampler, ConsecutiveDimensionsAreJointlyUniform) {
    const IndependentSampler sampler(4);
    const test_support::Grid2D grid{0, 1, 0, 1, 32, 32};
    const auto point = [&](std::size_t i) {
        const PixelSampleKey key{static_cast<uint32_t>(i % 64), static_cast<uint32_t>(i / 64), 9};
        return test_support::Point2{sampler.sample(key, 0), sampler.sample(key, 1)};
    };
    const auto result = test_support::chi_square_test_2d(grid, 200000, point, [](double, double) { return 1.0; });
    EXPECT_GT(result.p_value, sidak_significance(kSignificance, kStatisticalTests));
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    double mean_a = 0, mean_b = 0;
    for (size_t i = 0; i < a.size(); ++i) mean_a += a[i], mean_b += b[i];
    mean_a /= a.size(), mean_b /= b.size();
    double cov = 0, var_a = 0, var_b = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        cov += (a[i] - mean_a) * (b[i] - mean_b);
        var_a += (a[i] - mean_a) * (a[i] - mean_a);
        var_b += (b[i] - mean_b) * (b[i] - mean_b);
    }
    return cov / std::sqrt(var_a * var_b);
}

TEST(IndependentSampler, NeighbouringDimensionsSamplesAndPixelsAreUncorrelated) {
    const IndependentSampler sampler(5);
    constexpr uint32_t n = 100000;  // standard error of a correlation estimate: 1/sqrt(n) ~ 0.003
    std::vector<double> base(n), next_dimension(n), next_sample(n), next_pixel(n);
    for (uint32_t i = 0; i < n; ++i) {
        base[i] = sampler.sample({i, 0, 0}, 0);
        next_dimension[i] = sampler.sample({i, 0, 0}, 1);
        next_sample[i] = sampler.sample({i, 0, 1}, 0);
        next_pixel[i] = sampler.sample({i + 1, 0, 0}, 0);  // `base` one pixel on: lag-1 correlation
    }
    EXPECT_LT(std::abs(correlation(base, next_dimension)), 0.015);
    EXPECT_LT(std::abs(correlation(base, next_sample)), 0.015);
    EXPECT_LT(std::abs(correlation(base, next_pixel)), 0.015);
}

}  // namespace
}  // namespace isotrace
