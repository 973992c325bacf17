// RMSE, pbrt-v4's relative MSE and PSNR on small images worked by hand.
#include "renderer/image_compare/pixel_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace isotrace {
namespace {

RgbImage two_pixels(std::vector<float> values) {
    RgbImage image(2, 1);
    image.values = std::move(values);
    return image;
}

TEST(PixelError, AnImageAgainstItselfHasNoError) {
    const RgbImage image = two_pixels({0.1f, 2.0f, 0.0f, 7.5f, 0.25f, 1.0f});
    EXPECT_EQ(rmse(image, image), 0.0);
    EXPECT_EQ(relative_mse(image, image), 0.0);
    EXPECT_TRUE(std::isinf(psnr(image, image, 1.0)));
}

TEST(PixelError, RmseOfKnownDifferences) {
    // Differences 0, 1, 2, 0, 0, 0.5: mean square (1 + 4 + 0.25) / 6 = 0.875.
    const RgbImage reference = two_pixels({1, 0.25f, 0.5f, 2, 0, 0.125f});
    const RgbImage test = two_pixels({1, 1.25f, 2.5f, 2, 0, 0.625f});
    EXPECT_NEAR(rmse(reference, test), std::sqrt(0.875), 1e-12);
}

TEST(PixelError, RelativeMseIsPbrtsMrseWorkedByHand) {
    // Per value (t - r)^2 / (r + 0.01)^2, over all 6 values:
    //   red   (1.5 vs 1):    0.25 / 1.01^2      green (0.25 vs 0.25): 0     blue (0 vs 0.5):     0.25 / 0.51^2
    //   red   (3 vs 2):      1 / 2.01^2         green (1 vs 0):       1 / 0.01^2    blue (0.125 vs 0.125): 0
    const RgbImage reference = two_pixels({1, 0.25f, 0.5f, 2, 0, 0.125f});
    const RgbImage test = two_pixels({1.5f, 0.25f, 0, 3, 1, 0.125f});
    const double expected = (0.25 / (1.01 * 1.01) + 0.25 / (0.51 * 0.51) + 1 / (2.01 * 2.01) + 1 / (0.01 * 0.01)) / 6;
    EXPECT_NEAR(relative_mse(reference, test), expected, 1e-9 * expected);
}

TEST(PixelError, RelativeMseTakesTheFirstImageAsReference) {
    // Swapping the images changes the denominators: 1 / 1.01^2 against 1 / 2.01^2 for one value out of three.
    RgbImage a(1, 1, 1.0f), b(1, 1, 1.0f);
    b.values[0] = 2;
    EXPECT_NEAR(relative_mse(a, b), 1 / (1.01 * 1.01) / 3, 1e-12);
    EXPECT_NEAR(relative_mse(b, a), 1 / (2.01 * 2.01) / 3, 1e-12);
}

TEST(PixelError, PsnrOfAUniformShift) {
    // Every value 0.1 off: MSE 0.01, PSNR 10 log10(1 / 0.01) = 20 dB at peak 1, 20 + 20 log10(4) dB at peak 4.
    const RgbImage reference(4, 3, 0.5f), test(4, 3, 0.6f);
    EXPECT_NEAR(psnr(reference, test, 1.0), 20.0, 1e-5);
    EXPECT_NEAR(psnr(reference, test, 4.0), 20.0 + 20 * std::log10(4.0), 1e-5);
}

TEST(PixelError, PsnrPeakIsOneForDisplayImagesAndTheReferenceMaximumForHdr) {
    const RgbImage reference = two_pixels({0.5f, 12.0f, 3, 0, 0, 0});
    EXPECT_EQ(psnr_peak(reference, true), 1.0);
    EXPECT_EQ(psnr_peak(reference, false), 12.0);
    EXPECT_EQ(psnr_peak(RgbImage(2, 2, 0.0f), false), 1.0);
}

TEST(PixelError, ImagesOfDifferentSizeAreRefused) {
    EXPECT_THROW(rmse(RgbImage(2, 2), RgbImage(2, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
