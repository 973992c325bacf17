#include "renderer/image_compare/z_test.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace isotrace {

ZTestResult z_test(const ZTestInput& input, const ZTestSettings& settings) {
    require_same_size(input.reference_mean, input.test);
    require_same_size(input.reference_mean, input.reference_variance);
    const std::size_t pixels = input.test.pixel_count();
    if (input.reference_samples.size() != pixels || input.test_samples.size() != pixels)
        throw std::invalid_argument("z-test: one sample count per pixel is needed for both images");

    ZTestResult result;
    // 1 - (1 - s)^(1/N) without cancellation for large N.
    result.alpha = -std::expm1(std::log1p(-settings.significance) / double(pixels));
    result.failed_per_pixel.assign(pixels, 0.0f);
    for (std::size_t i = 0; i < pixels; ++i) {
        const double n_reference = input.reference_samples[i], n_test = input.test_samples[i];
        if (!(n_reference >= 1) || !(n_test >= 1))
            throw std::invalid_argument("z-test: pixel " + std::to_string(i % std::size_t(input.test.width)) + "," +
                                        std::to_string(i / std::size_t(input.test.width)) +
                                        " has a sample count below 1");
        for (int c = 0; c < 3; ++c) {
            const std::size_t k = 3 * i + std::size_t(c);
            const double sample_variance =
                std::max(double(input.reference_variance.values[k]) * n_reference, settings.variance_floor);
            const double standard_error = std::sqrt(sample_variance / n_test + sample_variance / n_reference);
            const double difference = double(input.test.values[k]) - double(input.reference_mean.values[k]);
            const double z = std::abs(difference) / standard_error;
            const double p = std::isnan(z) ? 0.0 : std::erfc(z / std::sqrt(2.0));
            result.min_p_value = std::min(result.min_p_value, p);
            if (!(p > result.alpha)) {
                ++result.failed_channels;
                result.failed_per_pixel[i] += 1;
            }
        }
    }
    const double total = 3.0 * double(pixels);
    result.pass_fraction = (total - double(result.failed_channels)) / total;
    result.passed = result.pass_fraction >= settings.required_pass_fraction;
    return result;
}

}  // namespace isotrace
