#include "renderer/image_compare/ssim.h"

#include <cstddef>
#include <numeric>
#include <stdexcept>

#include "renderer/image_compare/separable_filter.h"

namespace isotrace {

std::vector<float> ssim_map(const std::vector<float>& reference, const std::vector<float>& test, int width, int height,
                            double dynamic_range) {
    if (reference.size() != test.size()) throw std::invalid_argument("ssim: planes of different size");
    const Kernel1d window = normalised_gaussian(1.5, 5);  // 11 taps
    const auto blur = [&](const std::vector<float>& plane) {
        return filter_separable(plane, width, height, window, window);
    };
    // Moments of the values less each image's global mean: the same variances and covariance, without the
    // float cancellation of E[x^2] - E[x]^2 for bright, flat regions.
    const double offset_x = std::accumulate(reference.begin(), reference.end(), 0.0) / double(reference.size());
    const double offset_y = std::accumulate(test.begin(), test.end(), 0.0) / double(test.size());
    std::vector<float> x(reference.size()), y(reference.size()), xx(reference.size()), yy(reference.size()),
        xy(reference.size());
    for (std::size_t i = 0; i < reference.size(); ++i) {
        x[i] = float(reference[i] - offset_x);
        y[i] = float(test[i] - offset_y);
        xx[i] = x[i] * x[i];
        yy[i] = y[i] * y[i];
        xy[i] = x[i] * y[i];
    }
    const std::vector<float> shifted_mean_x = blur(x), shifted_mean_y = blur(y);
    const std::vector<float> second_xx = blur(xx), second_yy = blur(yy), second_xy = blur(xy);
    const double c1 = (0.01 * dynamic_range) * (0.01 * dynamic_range);
    const double c2 = (0.03 * dynamic_range) * (0.03 * dynamic_range);
    std::vector<float> map(reference.size());
    for (std::size_t i = 0; i < map.size(); ++i) {
        const double sx = shifted_mean_x[i], sy = shifted_mean_y[i];
        const double var_x = double(second_xx[i]) - sx * sx, var_y = double(second_yy[i]) - sy * sy;
        const double covariance = double(second_xy[i]) - sx * sy;
        const double mx = sx + offset_x, my = sy + offset_y;
        map[i] = float((2 * mx * my + c1) * (2 * covariance + c2) / ((mx * mx + my * my + c1) * (var_x + var_y + c2)));
    }
    return map;
}

double mean_ssim(const std::vector<float>& map) {
    return std::accumulate(map.begin(), map.end(), 0.0) / double(map.size());
}

}  // namespace isotrace
