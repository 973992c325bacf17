#pragma once
// FLIP, the perceptual difference of Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild
// ("FLIP: A Difference Evaluator for Alternating Images", HPG 2020), and its HDR extension (Andersson, Nilsson,
// Shirley and Akenine-Möller, "Visualizing Errors in Rendered High Dynamic Range Images", Eurographics 2021).
// Written from the papers' description; the constants are the papers'. Per pixel the error lies in [0, 1].
//
// LDR-FLIP, per image: linear RGB -> XYZ -> YCxCz; each opponent channel filtered by its contrast sensitivity
// function (sums of Gaussians at the given pixels per degree); back to linear RGB, clamped to [0, 1]; L*a*b* with
// the Hunt adjustment. Colour error: HyAB distance^0.7, redistributed so that 0.4 of the largest distance (green
// against blue) maps to 0.95. Feature error, on the luminance: the largest difference of edge (first Gaussian
// derivative) and point (second derivative) magnitudes, divided by sqrt(2), to the power 0.5. Per pixel:
// colour error ^ (1 - feature error).
// HDR-FLIP: both images exposure-compensated (2^e) and tone mapped (ACES fit) for exposures e from a start that
// maps the reference's brightest luminance to 0.85 up to a stop that maps its median to 0.85, at least two, about
// one per stop; the per-pixel maximum of the LDR-FLIP errors.
#include <vector>

#include "renderer/image_compare/rgb_image.h"

namespace isotrace {

// A 0.7 m wide 4K monitor seen from 0.7 m: 3840 pixels over 2 atan(0.5) ~ 1 radian, about 67 pixels per degree.
constexpr double kFlipDefaultPixelsPerDegree = 3840.0 * 3.14159265358979323846 / 180.0;

struct FlipMaps {
    std::vector<float> colour_error;   // in [0, 1]
    std::vector<float> feature_error;  // in [0, 1], the exponent's reduction
    std::vector<float> error;          // FLIP: colour_error ^ (1 - feature_error)
};

// LDR-FLIP of two images given as linear RGB (sRGB primaries) in [0, 1] (values outside are clamped).
FlipMaps ldr_flip_maps(const RgbImage& reference_linear, const RgbImage& test_linear, double pixels_per_degree);

// LDR-FLIP of two display-referred sRGB-encoded images in [0, 1].
std::vector<float> ldr_flip(const RgbImage& reference_srgb, const RgbImage& test_srgb, double pixels_per_degree);

struct FlipExposures {
    double start = 0, stop = 0;  // log2 exposure compensation
    int count = 2;
    double exposure(int i) const { return count > 1 ? start + i * (stop - start) / (count - 1) : start; }
};

// The exposure range HDR-FLIP derives from the reference (scene-linear, sRGB primaries): start = log2(x / Y_max),
// stop = log2(x / Y_median), where the tone mapper maps x to 0.85; count = max(2, ceil(stop - start)). The median
// is numpy's (mean of the middle two for an even count); if it is 0, the median of the positive luminances. An
// all-black reference gives start = stop = 0.
FlipExposures hdr_flip_exposures(const RgbImage& reference);

// The ACES filmic fit (Narkowicz 2016) with its 0.6 pre-exposure folded in, clamped to [0, 1]; negative -> 0.
double aces_tone_map(double x);

// HDR-FLIP of two scene-linear images (sRGB primaries).
std::vector<float> hdr_flip(const RgbImage& reference, const RgbImage& test, double pixels_per_degree,
                            const FlipExposures& exposures);

}  // namespace isotrace
