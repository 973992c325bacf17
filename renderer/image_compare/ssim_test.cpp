// SSIM (Wang et al. 2004) on cases with closed forms.
#include "renderer/image_compare/ssim.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace isotrace {
namespace {

std::vector<float> noise(int count) {
    std::vector<float> plane(static_cast<std::size_t>(count));
    std::uint32_t state = 12345;
    for (float& v : plane) {
        state = state * 1664525u + 1013904223u;
        v = float(state >> 8) / float(1 << 24);
    }
    return plane;
}

TEST(Ssim, AnImageAgainstItselfIsOne) {
    const std::vector<float> plane = noise(40 * 30);
    EXPECT_EQ(mean_ssim(ssim_map(plane, plane, 40, 30, 1.0)), 1.0);
}

TEST(Ssim, TwoUniformImagesKeepOnlyTheLuminanceTerm) {
    // No variance in either window: SSIM = (2 a b + C1) / (a^2 + b^2 + C1) * C2 / C2, C1 = 0.01^2.
    const double a = 0.2, b = 0.4, c1 = 1e-4;
    const std::vector<float> x(20 * 20, float(a)), y(20 * 20, float(b));
    EXPECT_NEAR(mean_ssim(ssim_map(x, y, 20, 20, 1.0)), (2 * a * b + c1) / (a * a + b * b + c1), 1e-6);
}

TEST(Ssim, AnImageAgainstItsNegativeIsBelowZero) {
    // 1 - x has the same mean (0.5 on average) and variance as x but covariance -var: the structure term is
    // (-2 var + C2) / (2 var + C2), near -1 for the noise's variance of 1/12.
    const std::vector<float> x = noise(32 * 32);
    std::vector<float> y(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) y[i] = 1 - x[i];
    const double value = mean_ssim(ssim_map(x, y, 32, 32, 1.0));
    EXPECT_LT(value, -0.9);
    EXPECT_GT(value, -1.0);
}

TEST(Ssim, AShiftLowersOnlyTheLuminanceTerm) {
    // x + 0.1: same variance and covariance = variance, so per pixel SSIM = (2 m (m + 0.1) + C1) / (m^2 + (m+0.1)^2 + C1)
    // with m the local mean near 0.5: about 0.98, never 1.
    const std::vector<float> x = noise(32 * 32);
    std::vector<float> y(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) y[i] = x[i] + 0.1f;
    const double m = 0.5;
    EXPECT_NEAR(mean_ssim(ssim_map(x, y, 32, 32, 1.0)),
                (2 * m * (m + 0.1) + 1e-4) / (m * m + (m + 0.1) * (m + 0.1) + 1e-4), 0.01);
}

}  // namespace
}  // namespace isotrace
