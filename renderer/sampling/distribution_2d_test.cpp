// Distribution2D: cell frequencies follow the weights (chi-square), uv is uniform inside a cell, the density
// integrates to 1 and matches what sample() reports, zero cells and rows are never chosen, bad input throws.
#include "renderer/sampling/distribution_2d.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "renderer/sampling/independent_sampler.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

// 5 columns x 4 rows; row 2 is all zero, and single zero cells elsewhere.
constexpr size_t kWidth = 5, kHeight = 4;
const std::vector<float> kWeights = {1, 2, 0, 4, 0.5f,  //
                                     0, 0, 8, 1, 1,     //
                                     0, 0, 0, 0, 0,     //
                                     3, 0.25f, 1, 1, 6};

double weight_sum() {
    double sum = 0;
    for (float w : kWeights) sum += w;
    return sum;
}

std::array<float, 2> u_sample(uint32_t i) {
    static const IndependentSampler sampler(2024);
    return {sampler.sample({i, 0, 0}, 0), sampler.sample({i, 0, 0}, 1)};
}

TEST(Distribution2D, CellsFollowTheWeights) {
    const Distribution2D distribution(kWeights, kWidth, kHeight);
    constexpr uint32_t samples = 200000;
    std::vector<double> observed(kWeights.size(), 0), expected;
    for (float w : kWeights) expected.push_back(samples * w / weight_sum());
    for (uint32_t i = 0; i < samples; ++i) {
        const auto s = distribution.sample(u_sample(i));
        ASSERT_GE(s.uv[0], 0.0f);
        ASSERT_LT(s.uv[0], 1.0f);
        ASSERT_GE(s.uv[1], 0.0f);
        ASSERT_LT(s.uv[1], 1.0f);
        ASSERT_EQ(s.column, size_t(s.uv[0] * kWidth));
        ASSERT_EQ(s.row, size_t(s.uv[1] * kHeight));
        ASSERT_GT(kWeights[s.row * kWidth + s.column], 0.0f);
        ASSERT_FLOAT_EQ(s.pdf, distribution.pdf(s.uv));
        observed[s.row * kWidth + s.column] += 1;
    }
    EXPECT_GT(test_support::chi_square_test(observed, expected).p_value, 0.01);
}

TEST(Distribution2D, SamplesFollowThePdfInsideCells) {
    // A finer histogram (3x3 bins per cell) against the integral of pdf(): catches uv that is not uniform
    // within its cell as well as wrong cell frequencies.
    const Distribution2D distribution(kWeights, kWidth, kHeight);
    constexpr uint32_t samples = 100000;
    const test_support::Grid2D grid{0, 1, 0, 1, int(kWidth) * 3, int(kHeight) * 3};
    const auto result = test_support::chi_square_test_2d(
        grid, samples,
        [&](std::size_t i) {
            const auto s = distribution.sample(u_sample(uint32_t(i)));
            return test_support::Point2{s.uv[0], s.uv[1]};
        },
        [&](double u, double v) { return double(distribution.pdf({float(u), float(v)})); });
    EXPECT_GT(result.p_value, 0.01) << "statistic " << result.statistic << " dof " << result.dof;
}

TEST(Distribution2D, PdfIntegratesToOneAndIsProportionalToTheWeights) {
    const Distribution2D distribution(kWeights, kWidth, kHeight);
    constexpr int steps = 200;  // midpoint rule: exact for a step function aligned with the grid
    double integral = 0;
    for (int j = 0; j < steps; ++j)
        for (int i = 0; i < steps; ++i)
            integral += distribution.pdf({(i + 0.5f) / steps, (j + 0.5f) / steps}) / (steps * steps);
    EXPECT_NEAR(integral, 1.0, 1e-5);
    for (size_t r = 0; r < kHeight; ++r)
        for (size_t c = 0; c < kWidth; ++c)
            EXPECT_NEAR(distribution.pdf({(c + 0.5f) / kWidth, (r + 0.5f) / kHeight}),
                        kWeights[r * kWidth + c] * kWidth * kHeight / weight_sum(), 1e-5);
}

TEST(Distribution2D, AllZeroIsUniformAndBadInputThrows) {
    const std::vector<float> zeros(6, 0.0f);
    const Distribution2D uniform(zeros, 3, 2);
    EXPECT_FLOAT_EQ(uniform.pdf({0.1f, 0.9f}), 1.0f);
    const auto s = uniform.sample({0.5f, 0.25f});
    EXPECT_NEAR(s.uv[0], 0.5f, 1e-6);
    EXPECT_NEAR(s.uv[1], 0.25f, 1e-6);
    EXPECT_THROW(Distribution2D(zeros, 4, 2), std::invalid_argument);
    EXPECT_THROW(Distribution2D(zeros, 0, 6), std::invalid_argument);
    EXPECT_THROW(Distribution2D(std::vector<float>{1, -1}, 2, 1), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
