// read_image_file: headers, channels, pixel types and metadata of what write_exr wrote; the before-pixels hook;
// files that are missing or not images; a missing image module.
#include "renderer/image/image_reader.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "renderer/core/input_error.h"
#include "renderer/image/image_writer.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

// 3x2 pixels of R, G, B and an integer id channel.
ImageBuffer small_image() {
    ImageBuffer image;
    image.width = 3;
    image.height = 2;
    image.channels = {"R", "G", "B", "objectId"};
    for (int i = 0; i < 24; ++i) image.pixels.push_back(i % 4 == 3 ? float(100000 + i) : 0.25f * float(i) - 1.0f);
    return image;
}

TEST(ImageReader, ReadsTheHeaderEveryChannelAndTheMetadata) {
    const testing::TemporaryDirectory directory("image_reader");
    const auto path = directory / "small.exr";
    ImageMetadata metadata;
    metadata.set("isotrace:spp", std::int64_t(-3));
    metadata.set("isotrace:scale", 0.5);
    metadata.set("isotrace:text", std::string("a b"));
    metadata.set("isotrace:vector", std::vector<float>{1.5f, -2.0f, 0.25f});
    const ImageBuffer image = small_image();
    write_exr(path, image, {{10, 8}, 2, 5}, true, metadata);

    const DecodedImage back = read_image_file(path);
    const ImageHeader& header = back.header;
    EXPECT_EQ(header.width, 3);
    EXPECT_EQ(header.height, 2);
    EXPECT_EQ(header.x, 2);
    EXPECT_EQ(header.y, 5);
    EXPECT_EQ(header.full_width, 10);
    EXPECT_EQ(header.full_height, 8);
    EXPECT_EQ(header.channel_names, image.channels);  // EXR readers put R, G, B first, then by name
    EXPECT_EQ(header.channel_file_types,
              (std::vector<PixelType>{PixelType::Half, PixelType::Half, PixelType::Half, PixelType::Float}));
    EXPECT_TRUE(is_floating_point(header.file_type));
    EXPECT_EQ(header.alpha_channel, -1);
    EXPECT_EQ(back.pixels, image.pixels);  // quarters are exact in half, the ids in float
    ASSERT_TRUE(header.metadata.find("isotrace:spp"));
    EXPECT_EQ(std::get<std::int64_t>(*header.metadata.find("isotrace:spp")), -3);
    EXPECT_EQ(std::get<double>(*header.metadata.find("isotrace:scale")), 0.5);
    EXPECT_EQ(std::get<std::string>(*header.metadata.find("isotrace:text")), "a b");
    EXPECT_EQ(std::get<std::vector<float>>(*header.metadata.find("isotrace:vector")),
              (std::vector<float>{1.5f, -2.0f, 0.25f}));
    EXPECT_EQ(header.metadata.find("isotrace:absent"), nullptr);
}

TEST(ImageReader, BeforePixelsSeesTheHeaderAndMayRefuseTheImage) {
    const testing::TemporaryDirectory directory("image_reader");
    const auto path = directory / "small.png";
    write_grey8_image(path, 3, 2, {0, 51, 102, 153, 204, 255}, {});
    ImageHeader seen;
    const DecodedImage back = read_image_file(path, [&](const ImageHeader& header) { seen = header; });
    EXPECT_EQ(seen.width, 3);
    EXPECT_EQ(seen.height, 2);
    EXPECT_EQ(seen.channel_names, std::vector<std::string>{"Y"});
    EXPECT_EQ(seen.file_type, PixelType::UInt8);
    EXPECT_FALSE(is_floating_point(seen.file_type));
    ASSERT_EQ(back.pixels.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) EXPECT_FLOAT_EQ(back.pixels[i], 0.2f * float(i));  // 8-bit values v / 255

    struct Refused {};
    EXPECT_THROW(read_image_file(path, [](const ImageHeader&) { throw Refused{}; }), Refused);
}

TEST(ImageReader, MissingFilesAndFilesThatAreNoImagesAreInputErrorsNamingThem) {
    const testing::TemporaryDirectory directory("image_reader");
    const std::pair<std::filesystem::path, std::string> cases[] = {
        {directory / "missing.exr", "file not found"},
        {directory.write("text.png", "not a PNG at all"), "cannot read image"},
        {directory.path(), "is a directory"}};
    for (const auto& [path, problem] : cases) {
        try {
            read_image_file(path);
            ADD_FAILURE() << path << " was read";
        } catch (const InputError& error) {
            EXPECT_EQ(error.location().file, path.string());
            EXPECT_NE(std::string(error.what()).find(problem), std::string::npos) << error.what();
        }
    }
}

// A FIFO would block the decoder forever, waiting for a writer.
TEST(ImageReader, AFifoIsRefusedWithoutBlocking) {
    const testing::TemporaryDirectory directory("image_reader");
    const std::filesystem::path fifo = directory / "sky.exr";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0);
    try {
        read_image_file(fifo);
        ADD_FAILURE() << "the FIFO was read";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("is a FIFO"), std::string::npos) << error.what();
    }
}

// Given a file its extension's reader refuses, OpenImageIO tries every reader it has, and some scan the whole file:
// 64 MB of zero bytes named .exr took 20 s to be refused. A file goes only to its extension's reader, and only when
// it starts with that format's signature.
TEST(ImageReader, FilesThatDoNotStartLikeTheirExtensionsFormatAreRefusedBeforeAnyReaderSeesThem) {
    const testing::TemporaryDirectory directory("image_reader");
    const auto message = [](const std::filesystem::path& path) -> std::string {
        try {
            read_image_file(path);
        } catch (const InputError& error) {
            EXPECT_EQ(error.location().file, path.string());
            return error.problem();
        }
        return "read";
    };
    for (const char* name : {"zeros.exr", "zeros.png", "zeros.tif", "zeros.jpg", "zeros.hdr"}) {
        const auto path = directory.write(name, "");
        std::filesystem::resize_file(path, std::uintmax_t(64) << 20);  // sparse: no disk space
        const std::string problem = message(path);
        EXPECT_NE(problem.find("cannot read image: its extension names the "), std::string::npos) << problem;
        EXPECT_NE(problem.find("format, but the file does not start with that format's signature"), std::string::npos)
            << problem;
    }
    const auto png = directory / "image.png";
    write_grey8_image(png, 1, 1, {7}, {});
    EXPECT_EQ(message(png), "read");
    const auto misnamed = directory / "image.jpg";
    std::filesystem::copy_file(png, misnamed);
    EXPECT_EQ(message(misnamed),
              "cannot read image: its extension names the JPEG format, but the file does not start with that format's "
              "signature");
    std::filesystem::copy_file(png, directory / "image.xyz");
    EXPECT_EQ(message(directory / "image.xyz").rfind(
                  "cannot read image: \".xyz\" is not the extension of an image format read here (.exr, .png, .jpg", 0),
              0u);
    std::filesystem::copy_file(png, directory / "image");
    EXPECT_EQ(message(directory / "image").rfind("cannot read image: the file name has no extension (.exr, ", 0), 0u);
}

// libpng allocates a text chunk's declared length before reading it: 2 GB for a 764-byte file.
TEST(ImageReader, APngChunkLongerThanTheFileIsRefusedBeforeLibpngAllocatesIt) {
    const testing::TemporaryDirectory directory("image_reader");
    const auto png = directory / "small.png";
    write_grey8_image(png, 2, 2, {1, 2, 3, 4}, {});
    std::string bytes = testing::read_file(png);
    const std::string huge_text("\x74\x75\x65\x65tEXtabc", 11);  // 1953850725 bytes claimed, 3 present
    bytes.insert(8 + 25, huge_text);  // after the signature and IHDR
    const auto corrupt = directory.write("corrupt.png", bytes);
    try {
        read_image_file(corrupt);
        ADD_FAILURE() << "the corrupt PNG was read";
    } catch (const InputError& error) {
        EXPECT_EQ(error.location().file, corrupt.string());
        EXPECT_NE(error.problem().find("the \"tEXt\" chunk at byte 33 claims 1953850725 bytes"), std::string::npos)
            << error.what();
    }
    EXPECT_NO_THROW(read_image_file(png));
}

TEST(ImageReader, AMissingImageModuleIsAnErrorNamingIt) {
    const testing::TemporaryDirectory directory("image_reader");
    const auto expect_error = [](const std::function<void()>& load, const std::string& expected) {
        try {
            load();
            ADD_FAILURE() << "a missing module was loaded";
        } catch (const std::runtime_error& error) {
            EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
        }
    };
    const auto image_module = directory / "libisotrace_oiio.so";
    expect_error([&] { load_image_codec(image_module); }, "cannot load the image module " + image_module.string());
    const auto exr_module = directory / "libisotrace_exr.so";
    expect_error([&] { load_exr_encoder(exr_module); }, "cannot load the EXR writer module " + exr_module.string());
}

}  // namespace
}  // namespace isotrace
