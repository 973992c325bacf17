#pragma once
// Structural similarity (Wang, Bovik, Sheikh and Simoncelli 2004, "Image quality assessment: from error
// visibility to structural similarity"), on one plane (isotrace diff uses luminance): local means, variances and
// covariance under an 11x11 Gaussian window with sigma 1.5, constants C1 = (0.01 L)^2 and C2 = (0.03 L)^2 for the
// dynamic range L. Unlike the paper's MATLAB code, which keeps only windows wholly inside the image, every pixel
// is scored and windows at the border repeat the edge pixels, so small images have an SSIM too. 1 = identical.
#include <vector>

namespace isotrace {

// The per-pixel SSIM index.
std::vector<float> ssim_map(const std::vector<float>& reference, const std::vector<float>& test, int width, int height,
                            double dynamic_range);

// The image's SSIM: the mean of its ssim_map().
double mean_ssim(const std::vector<float>& map);

}  // namespace isotrace
