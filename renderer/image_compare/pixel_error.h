#pragma once
// Per-pixel error measures between a reference and a test image, averaged over every pixel and all three
// channels. `reference` is always the image the test is measured against.
#include "renderer/image_compare/rgb_image.h"

namespace isotrace {

// Root of the mean of (test - reference)^2.
double rmse(const RgbImage& reference, const RgbImage& test);

// pbrt-v4's relative MSE (Image::MRSE): the mean of (test - reference)^2 / (reference + 0.01)^2. Terms that are
// not finite (a reference value of exactly -0.01) are left out of the sum, as pbrt does, but still counted.
double relative_mse(const RgbImage& reference, const RgbImage& test);
constexpr double kRelativeMseEpsilon = 0.01;

// 10 log10(peak^2 / MSE) in dB; +infinity for identical images.
double psnr(const RgbImage& reference, const RgbImage& test, double peak);

// The peak PSNR uses: 1 for display-referred images (values in [0, 1]); for scene-linear images the largest
// channel value of the reference (1 if it has none above 0), since HDR values have no fixed white.
double psnr_peak(const RgbImage& reference, bool display_referred);

}  // namespace isotrace
