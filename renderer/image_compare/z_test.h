#pragma once
// Mitsuba 3's statistical render test: is a low-budget render consistent with a reference's per-pixel mean?
// Per pixel and channel, z = |test - reference| / sqrt(s^2 / n_test + s^2 / n_reference), s^2 the per-sample
// variance (the reference's variance of the mean times its sample count, floored), and the two-sided p-value
// erfc(z / sqrt 2). A pixel channel passes when p exceeds the Sidak-corrected significance
// alpha = 1 - (1 - significance)^(1 / pixels); the image passes when at least 99.75 % of the pixel channels pass.
// Mitsuba's test leaves out the reference's own noise (s^2 / n_reference), assuming a converged reference; it is
// kept here so that a reference of modest sample count does not fail good renders.
#include <cstdint>
#include <vector>

#include "renderer/image_compare/rgb_image.h"

namespace isotrace {

struct ZTestSettings {
    double significance = 0.01;
    double variance_floor = 1e-4;   // per-sample variance; Mitsuba's value
    double required_pass_fraction = 0.9975;
};

struct ZTestInput {
    RgbImage reference_mean;
    RgbImage reference_variance;            // variance of the reference's pixel mean, per channel
    std::vector<float> reference_samples;   // samples per pixel
    RgbImage test;
    std::vector<float> test_samples;        // samples per pixel
};

struct ZTestResult {
    double pass_fraction = 0;   // of all pixel channels
    double alpha = 0;           // the corrected per-test significance
    double min_p_value = 1;
    std::int64_t failed_channels = 0;
    bool passed = false;
    std::vector<float> failed_per_pixel;  // 0..3 failing channels per pixel, for an error map
};

// Throws std::invalid_argument for mismatched sizes or sample counts below 1.
ZTestResult z_test(const ZTestInput& input, const ZTestSettings& settings = {});

}  // namespace isotrace
