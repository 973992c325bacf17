// The EXR writer module against the image module (OpenImageIO) that wrote every EXR before it: the same image
// must give the same file, byte for byte, so that nothing reading isotrace's EXRs can tell them apart.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "renderer/core/library_directory.h"
#include "renderer/image/image_codec.h"

namespace isotrace {
namespace {

ImageEncoding test_image(std::vector<float>& pixels) {
    ImageEncoding image;
    image.width = 5;
    image.height = 3;
    image.channel_names = {"R", "G", "B", "A", "Z", "objectId", "N.X"};
    pixels.resize(std::size_t(image.width * image.height) * image.channel_names.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = std::sin(float(i)) * float(i % 11) - 2.5f;
    image.pixels = pixels.data();
    image.file_type = PixelType::Half;
    image.channel_file_types = {PixelType::Half,  PixelType::Half,  PixelType::Half, PixelType::Half,
                                PixelType::Float, PixelType::Float, PixelType::Half};
    image.alpha_channel = 3;
    image.x = 2;  // a crop: the data window inside a larger display window
    image.y = 1;
    image.full_width = 9;
    image.full_height = 6;
    image.compression = "zip";
    image.metadata.set("DateTime", std::string("2026:01:02 03:04:05"));  // fixed: otherwise "now"
    image.metadata.set("Software", std::string("isotrace test"));
    image.metadata.set("isotrace:text", std::string("a b; c=d"));
    image.metadata.set("isotrace:real", 0.25);
    image.metadata.set("isotrace:count", std::int64_t(-7));
    image.metadata.set("isotrace:large", std::int64_t(5000000000));  // beyond 32 bits: text
    image.metadata.set("chromaticities", std::vector<float>{0.713f, 0.293f, 0.165f, 0.83f, 0.128f, 0.044f,
                                                            0.32168f, 0.33767f});
    for (const int length : {1, 2, 3, 4, 8, 9, 12, 16, 20}) {  // vectors, matrices and plain lists
        std::vector<float> list(static_cast<std::size_t>(length));
        for (int i = 0; i < length; ++i) list[std::size_t(i)] = 0.25f * float(i * i) - 1.5f;
        image.metadata.set("isotrace:list" + std::to_string(length), list);
    }
    return image;
}

TEST(OpenExrImageEncoder, WritesTheBytesTheImageModuleWrites) {
    std::vector<float> pixels;
    const ImageEncoding image = test_image(pixels);
    const std::vector<unsigned char> ours = image_encoder_for("image.exr").encode("image.exr", image);
    const std::vector<unsigned char> oiio =
        load_image_codec(library_directory() / "libisotrace_oiio.so").encode("image.exr", image);
    ASSERT_EQ(ours.size(), oiio.size());
    EXPECT_TRUE(ours == oiio);
}

TEST(OpenExrImageEncoder, WritesFullFloatWithoutCropOrMetadata) {
    std::vector<float> pixels;
    ImageEncoding image = test_image(pixels);
    image.file_type = PixelType::Float;
    image.channel_file_types.clear();
    image.x = image.y = image.full_width = image.full_height = 0;
    image.metadata = {};
    image.metadata.set("DateTime", std::string("2026:01:02 03:04:05"));
    const std::vector<unsigned char> ours = image_encoder_for("image.exr").encode("image.exr", image);
    const std::vector<unsigned char> oiio =
        load_image_codec(library_directory() / "libisotrace_oiio.so").encode("image.exr", image);
    EXPECT_TRUE(ours == oiio);
}

TEST(OpenExrImageEncoder, AnUnknownCompressionIsAnErrorNamingTheFile) {
    std::vector<float> pixels;
    ImageEncoding image = test_image(pixels);
    image.compression = "lzma";
    try {
        image_encoder_for("out.exr").encode("out.exr", image);
        FAIL() << "encoded with an unknown compression";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("cannot write out.exr: unknown EXR compression \"lzma\""),
                  std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace isotrace
