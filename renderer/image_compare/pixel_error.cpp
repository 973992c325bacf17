#include "renderer/image_compare/pixel_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isotrace {
namespace {

double mean_squared_error(const RgbImage& reference, const RgbImage& test) {
    require_same_size(reference, test);
    double sum = 0;
    for (std::size_t i = 0; i < reference.values.size(); ++i) {
        const double d = double(test.values[i]) - double(reference.values[i]);
        sum += d * d;
    }
    return sum / double(reference.values.size());
}

}  // namespace

double rmse(const RgbImage& reference, const RgbImage& test) { return std::sqrt(mean_squared_error(reference, test)); }

double relative_mse(const RgbImage& reference, const RgbImage& test) {
    require_same_size(reference, test);
    double sum = 0;
    for (std::size_t i = 0; i < reference.values.size(); ++i) {
        const double d = double(test.values[i]) - double(reference.values[i]);
        const double r = double(reference.values[i]) + kRelativeMseEpsilon;
        const double term = d * d / (r * r);
        if (std::isfinite(term)) sum += term;
    }
    return sum / double(reference.values.size());
}

double psnr(const RgbImage& reference, const RgbImage& test, double peak) {
    const double mse = mean_squared_error(reference, test);
    if (mse == 0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(peak * peak / mse);
}

double psnr_peak(const RgbImage& reference, bool display_referred) {
    if (display_referred) return 1.0;
    const float largest =
        reference.values.empty() ? 0.0f : *std::max_element(reference.values.begin(), reference.values.end());
    return largest > 0 ? double(largest) : 1.0;
}

}  // namespace isotrace
