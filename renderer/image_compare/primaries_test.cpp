// Conversion of scene-linear RGB to linear sRGB from the EXR chromaticities.
#include "renderer/image_compare/primaries.h"

#include <gtest/gtest.h>

namespace isotrace {
namespace {

TEST(Primaries, SrgbToSrgbIsTheIdentity) {
    const Transform map = to_linear_srgb(kSrgbChromaticities);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(map.matrix()[std::size_t(r)][std::size_t(c)], r == c ? 1 : 0, 1e-9);
}

TEST(Primaries, AcescgToSrgbMatchesThePublishedBradfordMatrix) {
    // ACEScg (AP1, ACES white ~D60) to linear Rec.709 with Bradford adaptation, as published (for example in the
    // colour-science package and OCIO's built-in transforms), to 4 decimals.
    const Transform map = to_linear_srgb({0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f});
    const double expected[3][3] = {
        {1.7051, -0.6218, -0.0833}, {-0.1303, 1.1408, -0.0105}, {-0.0240, -0.1290, 1.1530}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(map.matrix()[std::size_t(r)][std::size_t(c)], expected[r][c], 2e-4) << r << "," << c;
}

TEST(Primaries, WhiteStaysWhite) {
    // RGB (1, 1, 1) is the source white; Bradford maps it to D65, which is sRGB's (1, 1, 1).
    RgbImage image(1, 1, 1.0f);
    convert_colours(image, to_linear_srgb({0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f}));
    for (float v : image.values) EXPECT_NEAR(v, 1.0f, 1e-5f);
}

TEST(Primaries, DegenerateChromaticitiesAreRefused) {
    EXPECT_THROW(to_linear_srgb({0.64f, 0.0f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f}), std::invalid_argument);
    EXPECT_THROW(to_linear_srgb({0.3f, 0.3f, 0.3f, 0.3f, 0.3f, 0.3f, 0.3127f, 0.3290f}), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
