#pragma once
// Mitsuba 3's statistical render test, made stronger: is a low-budget render consistent with a reference's
// per-pixel mean? Welch-style: the difference of the two means over the root of the sum of both means' variances,
//   z = (test - reference) / sqrt(s_test^2 / n_test + s_reference^2 / n_reference),
// s^2 the per-sample variances: the reference's (its variance of the mean times its sample count, floored), and
// for the test its own when it has a variance channel, but never less than the reference's (under the hypothesis
// both renders estimate the same pixel and the reference's estimate rests on far more samples; a few-sample
// estimate is often too small, which would fail good renders). Two-sided p = erfc(|z| / sqrt 2).
// The test is made on single pixels and on square blocks of pixels (edges 4, 16, 64 and the whole image): a
// block's statistic is the sum of its pixels' relative differences (test - reference) / (|reference| + 0.01)
// over the root of the sum of their variances. Noise averages out over a block but a bias does not, so blocks
// find small biases that no single pixel shows (a 2 % brighter image at 256 spp). Relative differences keep a
// few bright, noisy pixels (an emitter's edge) from drowning a block, and their weights come from the reference
// mean, not from variance estimates: inverse-variance weights made the test reject unbiased renders (a pixel
// whose variance happened to come out small got a large weight and too little variance). Each level (pixels, each
// block size) gets significance / levels (Bonferroni) and its tests are Sidak-corrected:
// alpha = 1 - (1 - significance / levels)^(1 / tests). A level passes when at least 99.75 % of its tests (block or
// pixel, per channel) pass; the image passes when all do.
// Mitsuba's test leaves out the reference's own noise, assuming a converged reference; it is kept here so that
// a reference of modest sample count does not fail good renders. The two images must come from independent
// samples (different seeds).
#include <cstdint>
#include <vector>

#include "renderer/image_compare/rgb_image.h"

namespace isotrace {

struct ZTestSettings {
    double significance = 0.01;
    double variance_floor = 1e-4;   // per-sample variance; Mitsuba's value
    double required_pass_fraction = 0.9975;
    std::vector<int> block_edges = {4, 16, 64};  // block levels before the whole image; empty: pixels only
};

struct ZTestInput {
    RgbImage reference_mean;
    RgbImage reference_variance;            // variance of the reference's pixel mean, per channel
    std::vector<float> reference_samples;   // samples per pixel
    RgbImage test;
    std::vector<float> test_samples;        // samples per pixel
    RgbImage test_variance;                 // variance of the test's pixel mean; empty (0 x 0) when unknown
};

// One test of a level: the block of `edge` pixels (clipped at the image border) whose top-left pixel is x, y.
struct ZTestFailure {
    int edge = 1;
    int x = 0, y = 0;
    int channel = 0;   // 0, 1, 2 = R, G, B
    double test = 0, reference = 0;  // the block's mean values
    double z = 0, p_value = 0;
};

struct ZTestLevel {
    int edge = 1;               // block edge in pixels; 1 = single pixels
    std::int64_t tests = 0;     // blocks x 3 channels
    double alpha = 0;           // the corrected per-test significance
    std::int64_t failed = 0;
    double min_p_value = 1;
    double pass_fraction = 0;
    bool passed = false;
};

struct ZTestResult {
    std::vector<ZTestLevel> levels;       // pixels first, then blocks from small to large
    std::vector<ZTestFailure> worst;      // the failing tests with the smallest p-values, at most 12, smallest first
    std::vector<float> failed_per_pixel;  // 0..3 failing pixel channels per pixel, for an error map
    bool passed = false;
    const ZTestLevel& pixels() const { return levels.front(); }
};

// Throws std::invalid_argument for mismatched sizes or sample counts below 1.
ZTestResult z_test(const ZTestInput& input, const ZTestSettings& settings = {});

}  // namespace isotrace
