// FLIP against values computed independently: flip_expected_values.py (beside this file) evaluates the papers'
// formulas in plain Python with whole 2-D kernels, pixel by pixel; the features at an edge are also worked by hand.
#include "renderer/image_compare/flip.h"

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/image_compare/flip_colour.h"

namespace isotrace {
namespace {

constexpr double kPpd = kFlipDefaultPixelsPerDegree;

RgbImage uniform(int width, int height, float r, float g, float b) {
    RgbImage image(width, height);
    for (std::size_t i = 0; i < image.pixel_count(); ++i) {
        image.values[3 * i] = r;
        image.values[3 * i + 1] = g;
        image.values[3 * i + 2] = b;
    }
    return image;
}

TEST(Flip, DefaultViewingIsAbout67PixelsPerDegree) { EXPECT_NEAR(kFlipDefaultPixelsPerDegree, 67.0206, 1e-4); }

TEST(Flip, AnImageAgainstItselfIsZeroEverywhere) {
    RgbImage image(24, 20);
    for (std::size_t i = 0; i < image.values.size(); ++i) image.values[i] = float((i * 37) % 101) / 100.0f;
    for (float e : ldr_flip(image, image, kPpd)) EXPECT_EQ(e, 0.0f);
    for (float e : hdr_flip(image, image, kPpd, hdr_flip_exposures(image))) EXPECT_EQ(e, 0.0f);
}

TEST(Flip, UniformColourShiftIsTheColourErrorAlone) {
    // Uniform images: the CSF filters (normalised) keep the colour, the feature filters (weights summing to 0)
    // give 0, so FLIP = the redistributed HyAB^0.7 of the two colours. Python: 0.2850130162 for sRGB grey 0.5
    // against 0.6, 0.2844569768 for (0.8, 0.2, 0.2) against (0.7, 0.3, 0.2), 0.9673797626 for black against white.
    struct Case {
        float ref[3], test[3];
        double expected;
    };
    for (const Case& c : {Case{{0.5f, 0.5f, 0.5f}, {0.6f, 0.6f, 0.6f}, 0.2850130162},
                          Case{{0.8f, 0.2f, 0.2f}, {0.7f, 0.3f, 0.2f}, 0.2844569768},
                          Case{{0, 0, 0}, {1, 1, 1}, 0.9673797626}}) {
        const std::vector<float> map = ldr_flip(uniform(16, 12, c.ref[0], c.ref[1], c.ref[2]),
                                                uniform(16, 12, c.test[0], c.test[1], c.test[2]), kPpd);
        for (float e : map) EXPECT_NEAR(e, c.expected, 2e-6);
    }
}

// 32 x 8, black left of x = 16; right of it white in the reference and sRGB grey 0.5 in the test.
struct EdgeImages {
    RgbImage reference{32, 8}, test{32, 8};
    EdgeImages() {
        const float grey = float(flip::srgb_decode(0.5));
        for (int y = 0; y < 8; ++y)
            for (int x = 16; x < 32; ++x)
                for (int c = 0; c < 3; ++c) {
                    reference.pixel(x, y)[c] = 1;
                    test.pixel(x, y)[c] = grey;
                }
    }
};

TEST(Flip, EdgeFeatureErrorWorkedByHand) {
    // On the two pixels beside a step from luminance a to b, the balanced edge kernel (positive weights summing to
    // 1 on one side, negative to -1 on the other, 0 in the middle column) sees all of a and all of b: the edge
    // magnitude is |a - b| exactly, 1 in the reference and Y(sRGB 0.5) = 0.2140411 in the test. The point kernel's
    // response is smaller (|w0| / 2 times the step, w0 = -1 / 3.3456), so the feature error is
    // sqrt((1 - 0.2140411) / sqrt 2) = 0.7454910.
    const EdgeImages images;
    const FlipMaps maps = ldr_flip_maps(images.reference, images.test, kPpd);
    const double expected = std::sqrt((1 - flip::srgb_decode(0.5)) / std::sqrt(2.0));
    EXPECT_NEAR(expected, 0.7454910055, 1e-9);
    for (int y = 0; y < 8; ++y)
        for (int x : {15, 16}) EXPECT_NEAR(maps.feature_error[std::size_t(y * 32 + x)], expected, 1e-6) << x << "," << y;
}

TEST(Flip, EdgeMatchesTheIndependentCalculation) {
    // Python (flip_expected_values.py, whole 2-D kernels): colour, feature and FLIP at row 4. x = 2 is black in
    // both; x = 29 is 13 pixels from the edge, beyond both filters' reach (10 and 9 pixels), so it is the uniform
    // white-against-grey colour error with no feature error.
    const EdgeImages images;
    const FlipMaps maps = ldr_flip_maps(images.reference, images.test, kPpd);
    struct Expected {
        int x;
        double colour, feature, flip;
    };
    for (const Expected& e : {Expected{2, 0, 0, 0}, Expected{12, 0.0157319822, 0.5099648755, 0.1307255720},
                              Expected{15, 0.6431006883, 0.7454910055, 0.8937278152},
                              Expected{16, 0.7775482390, 0.7454910055, 0.9379703835},
                              Expected{20, 0.8470456063, 0.4412875952, 0.9114243591},
                              Expected{29, 0.8470462217, 0.0000000393, 0.8470462273}}) {
        const std::size_t i = std::size_t(4 * 32 + e.x);
        EXPECT_NEAR(maps.colour_error[i], e.colour, 2e-6) << e.x;
        EXPECT_NEAR(maps.feature_error[i], e.feature, 2e-4) << e.x;  // sqrt() amplifies float rounding near 0
        EXPECT_NEAR(maps.error[i], e.flip, 2e-5) << e.x;
    }
}

TEST(Flip, AcesToneMapperHitsItsKnownPoints) {
    EXPECT_EQ(aces_tone_map(0), 0);
    EXPECT_EQ(aces_tone_map(-3), 0);
    EXPECT_EQ(aces_tone_map(1e30), 1);
    // x = 2.1188723240 (the positive root of (k0 - 0.85 k3) x^2 + (k1 - 0.85 k4) x - 0.85 k5 = 0) maps to 0.85.
    EXPECT_NEAR(aces_tone_map(2.1188723240), 0.85, 1e-9);
}

TEST(Flip, HdrExposureRangeFromTheReferenceLuminance) {
    // Grey thirds of luminance 0.25, 1 and 3 (24 columns each): the brightest is 3, the median 1. The tone mapper
    // maps x = 2.1188723240 to 0.85, so start = log2(x / 3) = -0.5016658423, stop = log2(x / 1) = 1.0832966585,
    // and ceil(stop - start) = ceil(log2 3) = 2 exposures.
    RgbImage reference(72, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 72; ++x)
            for (int c = 0; c < 3; ++c) reference.pixel(x, y)[c] = x < 24 ? 0.25f : x < 48 ? 1.0f : 3.0f;
    const FlipExposures exposures = hdr_flip_exposures(reference);
    EXPECT_NEAR(exposures.start, -0.5016658423, 1e-7);
    EXPECT_NEAR(exposures.stop, 1.0832966585, 1e-7);
    EXPECT_EQ(exposures.count, 2);

    // The test 1.1 times as bright. Each third's middle column is 12 pixels from any change, beyond the filters:
    // there HDR-FLIP is the larger of the two exposures' uniform colour errors (Python: 0.1140048103 for 0.25,
    // 0.0870094453 for 1, 0.0439747618 for 3; the start exposure is the larger for all three).
    RgbImage test = reference;
    for (float& v : test.values) v *= 1.1f;
    const std::vector<float> map = hdr_flip(reference, test, kPpd, exposures);
    EXPECT_NEAR(map[2 * 72 + 12], 0.1140048103, 2e-6);
    EXPECT_NEAR(map[2 * 72 + 36], 0.0870094453, 2e-6);
    EXPECT_NEAR(map[2 * 72 + 60], 0.0439747618, 2e-6);
}

TEST(Flip, HdrExposureCountGrowsWithTheDynamicRange) {
    // Luminances 0.01, 0.02 (median) and 10 in thirds: stop - start = log2(10 / 0.02) = log2 500 = 8.97 -> 9.
    RgbImage reference(3, 1);
    const float values[3] = {0.01f, 0.02f, 10.0f};
    for (int x = 0; x < 3; ++x)
        for (int c = 0; c < 3; ++c) reference.pixel(x, 0)[c] = values[x];
    const FlipExposures exposures = hdr_flip_exposures(reference);
    EXPECT_NEAR(exposures.stop - exposures.start, std::log2(500.0), 1e-5);
    EXPECT_EQ(exposures.count, 9);
    // An all-black reference has no range.
    const FlipExposures black = hdr_flip_exposures(RgbImage(4, 4, 0.0f));
    EXPECT_EQ(black.start, 0);
    EXPECT_EQ(black.stop, 0);
}

TEST(Flip, MedianOfAMostlyBlackReferenceUsesThePositiveLuminances) {
    // 5 black pixels, then 0.5, 1 and 4: the median of all is 0, of the positive ones 1.
    RgbImage reference(8, 1, 0.0f);
    const float values[3] = {0.5f, 1.0f, 4.0f};
    for (int x = 5; x < 8; ++x)
        for (int c = 0; c < 3; ++c) reference.pixel(x, 0)[c] = values[x - 5];
    const FlipExposures exposures = hdr_flip_exposures(reference);
    EXPECT_NEAR(exposures.stop - exposures.start, 2.0, 1e-6);
}

}  // namespace
}  // namespace isotrace
