#pragma once
// Separable 2-D filtering of one image plane, the building block of SSIM's Gaussian window and of FLIP's
// contrast-sensitivity and feature filters. Correlation (not flipped), pixels beyond the border repeat the
// nearest edge pixel (FLIP's and OpenCV's BORDER_REPLICATE).
#include <vector>

namespace isotrace {

// A 1-D kernel of odd length 2r + 1; element r is the centre tap.
using Kernel1d = std::vector<double>;

// out(x, y) = sum_{i,j} along_x[i] along_y[j] plane(x + i - r_x, y + j - r_y). Rows run in parallel; each output
// pixel is summed in a fixed order, so the result does not depend on the thread count.
std::vector<float> filter_separable(const std::vector<float>& plane, int width, int height, const Kernel1d& along_x,
                                    const Kernel1d& along_y);

// exp(-k^2 / (2 sigma^2)) for k = -radius..radius, scaled to sum to 1.
Kernel1d normalised_gaussian(double sigma, int radius);

}  // namespace isotrace
