// Image writers, checked by reading the files back with read_image_file: EXR channels, pixel types, windows and
// metadata; display images against ColourSystem::to_display; failures leave no file; format detection.
#include "renderer/image/image_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "renderer/colour/colour_system.h"
#include "renderer/core/input_error.h"
#include "renderer/image/image_reader.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

namespace fs = std::filesystem;

// A 5x3 image with beauty and every kind of AOV channel; values that half floats cannot hold exactly.
ImageBuffer test_image() {
    ImageBuffer image;
    image.width = 5;
    image.height = 3;
    image.channels = {"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "Z", "P.X", "P.Y", "P.Z",
                      "objectId", "primitiveId", "sampleCount", "variance.R", "variance.G", "variance.B"};
    image.pixels.resize(std::size_t(image.width * image.height) * image.channels.size());
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const std::size_t c = i % image.channels.size();
        const float base = 0.1234567f * float(i + 1);
        image.pixels[i] = c == 11 ? float(100003 + i) : c == 12 ? float(70001 + 3 * i) : c == 13 ? 4097.0f : base;
    }
    return image;
}

ImageMetadata test_metadata() {
    ImageMetadata metadata;
    metadata.set("isotrace:spp", std::int64_t(64));
    metadata.set("isotrace:seed", std::string("18446744073709551615"));
    metadata.set("isotrace:render_seconds", 1.5);
    metadata.set("isotrace:integrator", std::string("preview"));
    metadata.set("isotrace:partial", std::int64_t(0));
    return metadata;
}

// An attribute of `type`; a test failure if it is missing or of another type.
template <class Type>
Type attribute(const DecodedImage& image, const std::string& name) {
    const ImageMetadata::Value* value = image.header.metadata.find(name);
    if (!value || !std::holds_alternative<Type>(*value)) {
        ADD_FAILURE() << "no attribute " << name << " of the expected type";
        return {};
    }
    return std::get<Type>(*value);
}

// The pixels as 8-bit values (read_image_file gives v / 255).
std::vector<int> bytes_of(const DecodedImage& image) {
    std::vector<int> bytes;
    for (float v : image.pixels) bytes.push_back(int(std::lround(v * 255.0f)));
    return bytes;
}

// EXR stores channels sorted by name and readers choose their own order (OIIO: RGBA first, then Z, then the
// rest), so a file is compared with the buffer channel by channel, by name.
void expect_same_channels(const DecodedImage& back, const ImageBuffer& image, bool exact) {
    std::vector<std::string> written = image.channels, read = back.header.channel_names;
    std::sort(written.begin(), written.end());
    std::sort(read.begin(), read.end());
    ASSERT_EQ(read, written);
    ASSERT_EQ(back.header.channel_names.size(), image.channels.size());
    const std::vector<std::string> beauty = {"R", "G", "B", "A"};
    EXPECT_EQ(std::vector<std::string>(back.header.channel_names.begin(), back.header.channel_names.begin() + 4), beauty);
    const std::size_t n = image.channels.size();
    for (std::size_t c = 0; c < n; ++c) {
        const auto& names = back.header.channel_names;
        const std::size_t k = std::size_t(std::find(names.begin(), names.end(), image.channels[c]) - names.begin());
        for (std::size_t p = 0; p < std::size_t(image.width * image.height); ++p) {
            const float original = image.pixels[p * n + c], read_value = back.pixels[p * n + k];
            if (exact) {
                EXPECT_EQ(read_value, original) << image.channels[c] << " pixel " << p;
            } else {
                EXPECT_NEAR(read_value, original, std::abs(original) * 1e-3) << image.channels[c];  // half: 11 bits
            }
        }
    }
}

TEST(ImageWriter, ExrKeepsChannelNamesOrderAndFloatValues) {
    const testing::TemporaryDirectory dir("image-writer");
    const ImageBuffer image = test_image();
    const fs::path path = dir.path() / "out.exr";
    write_exr(path, image, {{5, 3}, 0, 0}, false, test_metadata());
    const DecodedImage back = read_image_file(path);
    expect_same_channels(back, image, true);  // bit for bit
    EXPECT_EQ(back.header.width, 5);
    EXPECT_EQ(back.header.height, 3);
    EXPECT_EQ(back.header.alpha_channel, 3);
    EXPECT_EQ(back.header.file_type, PixelType::Float);
    EXPECT_EQ(back.header.channel_file_types, std::vector<PixelType>(image.channels.size(), PixelType::Float));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.exr"});  // no temporary left behind
}

TEST(ImageWriter, HalfExrKeepsIdsCountsDepthAndPositionsAsFloat) {
    const testing::TemporaryDirectory dir("image-writer");
    const ImageBuffer image = test_image();
    const fs::path path = dir.path() / "half.exr";
    write_exr(path, image, {{5, 3}, 0, 0}, true, test_metadata());
    const DecodedImage back = read_image_file(path);
    expect_same_channels(back, image, false);
    const std::size_t n = image.channels.size();
    for (std::size_t c = 0; c < n; ++c) {
        const std::string& name = image.channels[c];
        const bool exact = name == "objectId" || name == "primitiveId" || name == "sampleCount" || name == "Z" ||
                           name.rfind("P.", 0) == 0;
        const auto& names = back.header.channel_names;
        const std::size_t k = std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
        ASSERT_LT(k, n) << name;
        EXPECT_EQ(back.header.channel_file_types[k], exact ? PixelType::Float : PixelType::Half) << name;
        if (!exact) continue;
        for (std::size_t p = 0; p < 15; ++p) EXPECT_EQ(back.pixels[p * n + k], image.pixels[p * n + c]) << name;
    }
    // Ids beyond half's range really needed the float channel: 100003 is not representable as a half.
    EXPECT_GT(image.pixels[11], 65504.0f);
}

TEST(ImageWriter, CropWindowBecomesTheDataWindowInsideTheDisplayWindow) {
    const testing::TemporaryDirectory dir("image-writer");
    const ImageBuffer image = test_image();
    const fs::path path = dir.path() / "crop.exr";
    write_exr(path, image, {{48, 40}, 7, 11}, false, {});
    const DecodedImage back = read_image_file(path);
    EXPECT_EQ(back.header.x, 7);
    EXPECT_EQ(back.header.y, 11);
    EXPECT_EQ(back.header.width, 5);
    EXPECT_EQ(back.header.height, 3);
    EXPECT_EQ(back.header.full_x, 0);
    EXPECT_EQ(back.header.full_y, 0);
    EXPECT_EQ(back.header.full_width, 48);
    EXPECT_EQ(back.header.full_height, 40);
    expect_same_channels(back, image, true);
}

TEST(ImageWriter, MetadataAttributesArePresent) {
    const testing::TemporaryDirectory dir("image-writer");
    const fs::path path = dir.path() / "meta.exr";
    ImageMetadata metadata = test_metadata();
    metadata.set("isotrace:big", std::int64_t(1) << 40);  // beyond a 32-bit attribute
    write_exr(path, test_image(), {{5, 3}, 0, 0}, false, metadata);
    const DecodedImage back = read_image_file(path);
    EXPECT_EQ(attribute<std::int64_t>(back, "isotrace:spp"), 64);
    EXPECT_EQ(attribute<std::int64_t>(back, "isotrace:partial"), 0);
    EXPECT_EQ(attribute<std::string>(back, "isotrace:seed"), "18446744073709551615");
    EXPECT_EQ(attribute<std::string>(back, "isotrace:integrator"), "preview");
    EXPECT_FLOAT_EQ(float(attribute<double>(back, "isotrace:render_seconds")), 1.5f);
    // A value that does not fit the file's 32-bit integer attribute must not be silently wrapped.
    EXPECT_EQ(attribute<std::string>(back, "isotrace:big"), "1099511627776");
    EXPECT_EQ(attribute<std::string>(back, "compression"), "zip");
}

TEST(ImageWriter, DisplayImageMatchesTheColourSystemsDisplayTransform) {
    const testing::TemporaryDirectory dir("image-writer");
    const ColourSystem colours("");
    ImageBuffer image;
    image.width = 7;
    image.height = 4;
    image.channels = {"R", "G", "B", "A", "Z"};
    std::mt19937 random(3);
    std::uniform_real_distribution<float> value(-0.2f, 3.0f);
    image.pixels.resize(std::size_t(image.width * image.height) * image.channels.size());
    for (float& v : image.pixels) v = value(random);
    image.pixels[0] = std::numeric_limits<float>::quiet_NaN();  // becomes 0, not garbage
    image.pixels[6] = std::numeric_limits<float>::infinity();
    for (const auto& [display, view] : {std::pair<std::string, std::string>{"", ""},
                                        std::pair<std::string, std::string>{"sRGB", "ACES 1.0 - SDR Video"}}) {
        const fs::path path = dir.path() / ("display" + view.substr(0, 4) + ".png");
        write_display_image(path, image, colours, display, view, test_metadata());
        const DecodedImage back = read_image_file(path);
        EXPECT_EQ(back.header.width, 7);
        EXPECT_EQ(back.header.height, 4);
        ASSERT_EQ(back.header.channel_names.size(), 3u);
        EXPECT_EQ(back.header.file_type, PixelType::UInt8);
        const std::vector<int> bytes = bytes_of(back);

        std::vector<float> rgb(std::size_t(7 * 4 * 3));
        for (std::size_t p = 0; p < 28; ++p)
            for (std::size_t c = 0; c < 3; ++c) rgb[p * 3 + c] = image.pixels[p * 5 + c];
        colours.to_display(rgb.data(), 28, 3, display, view);
        for (std::size_t i = 0; i < rgb.size(); ++i) {
            const float v = std::isfinite(rgb[i]) ? std::clamp(rgb[i], 0.0f, 1.0f) : 0.0f;
            EXPECT_EQ(bytes[i], int(std::lround(v * 255.0f))) << view << " value " << i;
        }
    }
}

// PNG, JPEG and TIFF carried no isotrace:partial/spp/render_seconds, so an interrupted render could not be told
// from a finished one. (TIFFs encoded through an OIIO memory proxy lose their size tags: they must read back.)
TEST(ImageWriter, DisplayImagesOfEveryFormatCarryTheRenderMetadata) {
    const testing::TemporaryDirectory dir("image-writer");
    const ColourSystem colours("");
    ImageMetadata metadata = test_metadata();
    metadata.set("isotrace:partial", std::int64_t(1));
    for (const std::string format : {"png", "jpg", "tif"}) {
        const fs::path path = dir.path() / ("meta." + format);
        write_display_image(path, test_image(), colours, "", "", metadata);
        const DecodedImage back = read_image_file(path);
        EXPECT_EQ(back.header.width, 5) << format;
        EXPECT_EQ(back.header.height, 3) << format;
        const std::string description = attribute<std::string>(back, "ImageDescription");
        for (const char* entry : {"isotrace:partial=1", "isotrace:spp=64", "isotrace:render_seconds=1.5",
                                  "isotrace:seed=18446744073709551615"})
            EXPECT_NE(description.find(entry), std::string::npos) << format << ": " << description;
        if (format == "png") {  // text chunks keep every entry under its own name
            EXPECT_EQ(attribute<std::string>(back, "isotrace:partial"), "1");
            EXPECT_EQ(attribute<std::string>(back, "isotrace:spp"), "64");
        }
    }
}

TEST(ImageWriter, FailedWriteLeavesNoFile) {
    const testing::TemporaryDirectory dir("image-writer");
    const ImageBuffer image = test_image();
    // Missing directory.
    const fs::path missing = dir.path() / "no" / "such" / "dir" / "out.exr";
    EXPECT_ANY_THROW(write_exr(missing, image, {{5, 3}, 0, 0}, false, {}));
    EXPECT_FALSE(fs::exists(missing));
    EXPECT_FALSE(fs::exists(dir.path() / "no"));
    const ColourSystem colours("");
    EXPECT_ANY_THROW(write_display_image(dir.path() / "no" / "out.png", image, colours, "", "", {}));
    EXPECT_TRUE(dir.entries().empty());

    // The target is in the way (a directory): the temporary written beside it is removed again.
    fs::create_directories(dir.path() / "taken.exr" / "child");
    EXPECT_ANY_THROW(write_exr(dir.path() / "taken.exr", image, {{5, 3}, 0, 0}, false, {}));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken.exr"});
    EXPECT_TRUE(fs::is_directory(dir.path() / "taken.exr"));

    // An existing good file survives a failed rewrite untouched.
    const fs::path good = dir.path() / "good.exr";
    write_exr(good, image, {{5, 3}, 0, 0}, false, {});
    const auto size = fs::file_size(good);
    ImageBuffer broken = image;
    broken.width = 0;  // no pixels: the encoder refuses to open the output
    EXPECT_ANY_THROW(write_exr(good, broken, {{5, 3}, 0, 0}, false, {}));
    EXPECT_EQ(fs::file_size(good), size);
    expect_same_channels(read_image_file(good), image, true);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"good.exr", "taken.exr"}));
}

TEST(ImageWriter, ImageKindFollowsTheExtension) {
    EXPECT_EQ(image_kind_for("a/b/out.exr"), ImageKind::Exr);
    EXPECT_EQ(image_kind_for("OUT.EXR"), ImageKind::Exr);
    for (const char* name : {"x.png", "x.PNG", "x.jpg", "x.jpeg", "x.JPeg", "x.tif", "x.tiff"})
        EXPECT_EQ(image_kind_for(name), ImageKind::Display) << name;
    for (const char* name : {"x.bmp", "x", "x.exr.gz", "png", "dir.exr/file"}) {
        try {
            image_kind_for(name);
            ADD_FAILURE() << name << " was accepted";
        } catch (const InputError& error) {
            EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << error.what();
            EXPECT_NE(std::string(error.what()).find(".exr"), std::string::npos) << error.what();
        }
    }
}

}  // namespace
}  // namespace isotrace
