// Picking colour channels out of image files, and the errors that name the file and the pixel.
#include "renderer/image_compare/image_channels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

ImageFile file_with(std::vector<std::string> channels, std::vector<float> pixels, int width = 2) {
    ImageFile file;
    file.width = width;
    file.height = 1;
    file.channels = std::move(channels);
    file.pixels = std::move(pixels);
    return file;
}

TEST(ImageChannels, ColourComesFromRgbInAnyOrder) {
    const ImageFile file = file_with({"B", "A", "R", "G"}, {3, 1, 1, 2, 6, 1, 4, 5});
    const RgbImage image = colour_of(file, "x.exr");
    EXPECT_EQ(image.values, (std::vector<float>{1, 2, 3, 4, 5, 6}));
}

TEST(ImageChannels, AGreyChannelStandsForAllThree) {
    EXPECT_EQ(colour_of(file_with({"Y"}, {0.25f, 0.5f}), "g.png").values,
              (std::vector<float>{0.25f, 0.25f, 0.25f, 0.5f, 0.5f, 0.5f}));
    EXPECT_EQ(colour_of(file_with({"Z"}, {1, 2}), "z.exr").values, (std::vector<float>{1, 1, 1, 2, 2, 2}));
}

TEST(ImageChannels, MissingColourAndNonFiniteValuesAreInputErrors) {
    try {
        colour_of(file_with({"N.X", "N.Y"}, {0, 0, 0, 0}), "n.exr");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("n.exr: no colour channels"), std::string::npos) << error.what();
    }
    try {
        colour_of(file_with({"R", "G", "B"}, {0, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0}), "nan.exr");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("nan.exr: pixel 1,0 has a value that is not finite"), std::string::npos)
            << error.what();
    }
    try {
        channel_plane(file_with({"R", "G", "B"}, {0, 0, 0, 0, 0, 0}), "sampleCount", "ref.exr");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("no channel \"sampleCount\" (channels: R, G, B)"), std::string::npos)
            << error.what();
    }
}

TEST(ImageChannels, ChromaticitiesConvertScenelinearColour) {
    // ACEScg white (1, 1, 1) stays white in linear sRGB; ACEScg red does not stay (1, 0, 0).
    ImageFile file = file_with({"R", "G", "B"}, {1, 1, 1, 1, 0, 0});
    file.chromaticities = std::array<float, 8>{0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f};
    const RgbImage image = linear_srgb_colour_of(file, "acescg.exr");
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.values[std::size_t(c)], 1.0f, 1e-5f);
    EXPECT_NEAR(image.values[3], 1.7051f, 2e-4f);
    file.chromaticities = std::array<float, 8>{0.64f, 0.0f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
    EXPECT_THROW(linear_srgb_colour_of(file, "bad.exr"), InputError);
}

}  // namespace
}  // namespace isotrace
