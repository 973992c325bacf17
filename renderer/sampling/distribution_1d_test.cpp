#include "renderer/sampling/distribution_1d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "renderer/sampling/independent_sampler.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

const std::vector<float> kWeights = {0, 1, 2, 0, 5, 0.5f, 3, 0, 0.25f, 0};
constexpr float kLargestBelowOne = 1.0f - 0x1p-24f;

float u_sample(uint32_t i) {
    static const IndependentSampler sampler(77);
    return sampler.sample({i, 0, 0}, 0);
}

TEST(Distribution1D, PdfIntegratesToOne) {
    const Distribution1D distribution(kWeights);
    constexpr int steps = 10000;  // midpoint rule; exact for a step function whose steps align with it
    double integral = 0;
    for (int i = 0; i < steps; ++i) integral += distribution.pdf((i + 0.5f) / steps) / steps;
    EXPECT_NEAR(integral, 1.0, 1e-6);
    EXPECT_FLOAT_EQ(distribution.integral(), 11.75f / 10);
}

TEST(Distribution1D, ContinuousSamplesFollowTheWeights) {
    const Distribution1D distribution(kWeights);
    constexpr uint32_t samples = 200000;
    std::vector<double> observed(kWeights.size(), 0), expected;
    for (float w : kWeights) expected.push_back(samples * w / 11.75);
    for (uint32_t i = 0; i < samples; ++i) {
        const auto sample = distribution.sample_continuous(u_sample(i));
        ASSERT_GE(sample.x, 0.0f);
        ASSERT_LT(sample.x, 1.0f);
        ASSERT_EQ(sample.bin, static_cast<size_t>(sample.x * kWeights.size()));
        ASSERT_FLOAT_EQ(sample.pdf, distribution.pdf(sample.x));
        observed[sample.bin] += 1;
    }
    // Zero-weight bins expect nothing, so a single sample there would make p = 0.
    EXPECT_GT(test_support::chi_square_test(observed, expected).p_value, 0.01);
}

TEST(Distribution1D, DiscreteSamplesFollowTheWeights) {
    const Distribution1D distribution(kWeights);
    constexpr uint32_t samples = 200000;
    std::vector<double> observed(kWeights.size(), 0), expected;
    for (size_t i = 0; i < kWeights.size(); ++i) {
        expected.push_back(samples * distribution.probability(i));
        EXPECT_FLOAT_EQ(distribution.probability(i), kWeights[i] / 11.75f);
    }
    for (uint32_t i = 0; i < samples; ++i) {
        const auto sample = distribution.sample_discrete(u_sample(i));
        ASSERT_EQ(sample.probability, distribution.probability(sample.index));
        observed[sample.index] += 1;
    }
    EXPECT_GT(test_support::chi_square_test(observed, expected).p_value, 0.01);
}

TEST(Distribution1D, ZeroWeightBinsAreNeverSampledEvenAtBoundaries) {
    // u exactly on CDF steps (multiples of 1/8 here) and at the ends of [0,1) are where a careless search
    // returns an empty bin.
    const std::vector<float> weights = {0, 1, 0, 0, 2, 1, 0, 4, 0};
    const Distribution1D distribution(weights);
    std::vector<float> us = {0.0f, kLargestBelowOne};
    for (int k = 0; k <= 8; ++k) {
        const float step = k / 8.0f;
        us.insert(us.end(), {step, std::nextafter(step, 0.0f), std::nextafter(step, 1.0f)});
    }
    for (uint32_t i = 0; i < 10000; ++i) us.push_back(u_sample(i));
    for (float u : us) {
        if (!(u >= 0.0f && u < 1.0f)) continue;
        EXPECT_GT(weights[distribution.sample_continuous(u).bin], 0.0f) << "u=" << u;
        EXPECT_GT(weights[distribution.sample_discrete(u).index], 0.0f) << "u=" << u;
        EXPECT_LT(distribution.sample_continuous(u).x, 1.0f);
    }
}

TEST(Distribution1D, AllZeroWeightsAreUniform) {
    const std::vector<float> zeros(4, 0.0f);
    const Distribution1D distribution(zeros);
    EXPECT_EQ(distribution.integral(), 0.0f);
    EXPECT_FLOAT_EQ(distribution.pdf(0.3f), 1.0f);
    EXPECT_FLOAT_EQ(distribution.probability(2), 0.25f);
    const auto sample = distribution.sample_continuous(0.6f);
    EXPECT_FLOAT_EQ(sample.x, 0.6f);
    EXPECT_EQ(sample.bin, 2u);
}

TEST(Distribution1D, InvalidWeightsThrow) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_THROW(Distribution1D(std::vector<float>{}), std::invalid_argument);
    EXPECT_THROW(Distribution1D(std::vector<float>{1, -0.5f}), std::invalid_argument);
    EXPECT_THROW(Distribution1D(std::vector<float>{1, nan}), std::invalid_argument);
    EXPECT_THROW(Distribution1D(std::vector<float>{inf, 1}), std::invalid_argument);
}

TEST(Distribution1D, SingleBinIsUniform) {
    const Distribution1D distribution(std::vector<float>{3});
    EXPECT_FLOAT_EQ(distribution.integral(), 3.0f);
    const auto sample = distribution.sample_continuous(0.25f);
    EXPECT_FLOAT_EQ(sample.x, 0.25f);
    EXPECT_FLOAT_EQ(sample.pdf, 1.0f);
    for (const float u : {0.0f, 0.5f, 0.999f}) {
        EXPECT_EQ(distribution.sample_discrete(u).index, 0u);
        EXPECT_EQ(distribution.sample_discrete(u).probability, distribution.probability(0));
        EXPECT_EQ(distribution.probability(0), 1.0f);
    }
    const Distribution1D all_zero(std::vector<float>{0});
    EXPECT_EQ(all_zero.sample_discrete(0.3f).probability, all_zero.probability(0));
}

}  // namespace
}  // namespace isotrace
