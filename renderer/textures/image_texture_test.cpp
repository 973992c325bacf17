#include "renderer/textures/image_texture.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "renderer/colour/colour_system.h"
#include "renderer/core/input_error.h"
#include "renderer/core/memory_budget.h"
#include "renderer/image/image_codec.h"
#include "tests/support/scene_files.h"
#include "tests/support/test_images.h"

namespace isotrace {
namespace {

MemoryBudget memory;  // the default limit (80 % of physical memory)

// The images the tests write, removed when the test process exits (it was left behind in /tmp, once per run).
const std::filesystem::path& temp_dir() {
    static const testing::TemporaryDirectory directory("texture");
    return directory.path();
}

template <class T>
std::filesystem::path write_image(const std::string& name, int w, int h, const std::vector<T>& pixels) {
    return testing::write_rgb_image(temp_dir() / name, w, h, pixels);
}

// The full-resolution bilinear lookup, repeating.
Rgb lookup(const ImageTexture& texture, std::array<float, 2> uv) {
    return ImageTexture::to_rgb(texture.pyramid().lookup<3>(uv, 0, WrapMode::Repeat));
}

// The message of the InputError that loading `path` throws; a test failure (and "") if it loads.
std::string load_error(const std::filesystem::path& path, const ColourSystem& colours, MemoryBudget& budget = memory) {
    try {
        ImageTexture::load(path, "", colours, budget);
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "expected InputError for " << path;
    return "";
}

TEST(ImageTexture, EightBitImagesAreDecodedFromSrgb) {
    const ColourSystem colours("", "lin_rec709");
    // 2x1 image: left texel 128/255, right texel 255.
    const auto path = write_image<std::uint8_t>("srgb.png", 2, 1, {128, 128, 128, 255, 255, 255});
    const auto texture = ImageTexture::load(path, "", colours, memory);
    EXPECT_EQ(texture->colour_space(), "srgb_texture");
    const float expected = std::pow((128.0f / 255 + 0.055f) / 1.055f, 2.4f);  // the sRGB EOTF
    const Rgb left = lookup(*texture, {0.25f, 0.5f});  // texel centre: no blending
    EXPECT_NEAR(left.r, expected, 1e-5);
    EXPECT_NEAR(lookup(*texture, {0.75f, 0.5f}).g, 1.0f, 1e-5);
    // Halfway between the texel centres the bilinear lookup averages them.
    EXPECT_NEAR(lookup(*texture, {0.5f, 0.5f}).b, 0.5f * (expected + 1.0f), 1e-5);
}

TEST(ImageTexture, FloatImagesDefaultToTheWorkingSpaceAndVRunsUp) {
    const ColourSystem colours("", "ACEScg");
    // 1x2 float image: top row red, bottom row green.
    const auto path = write_image<float>("rows.exr", 1, 2, {1, 0, 0, 0, 1, 0});
    const auto texture = ImageTexture::load(path, "", colours, memory);
    EXPECT_EQ(texture->colour_space(), "ACEScg");
    EXPECT_EQ(lookup(*texture, {0.5f, 0.75f}), Rgb(1, 0, 0));  // v = 0.75 is the top row's centre
    EXPECT_EQ(lookup(*texture, {0.5f, 0.25f}), Rgb(0, 1, 0));
}

TEST(ImageTexture, ExplicitSpaceIsConvertedToTheWorkingSpace) {
    const ColourSystem colours("", "ACEScg");
    const auto path = write_image<float>("white.exr", 1, 1, {1, 0, 0});
    const Rgb converted = lookup(*ImageTexture::load(path, "lin_rec709", colours, memory), {0.3f, 0.6f});
    EXPECT_EQ(converted, colours.to_working(Rgb(1, 0, 0), "lin_rec709"));
    EXPECT_NE(converted, Rgb(1, 0, 0));
}

TEST(ImageTexture, RepeatsOutsideTheUnitSquare) {
    const ColourSystem colours("", "ACEScg");
    const auto path = write_image<float>("ramp.exr", 4, 1,
                                         {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3});
    const auto texture = ImageTexture::load(path, "", colours, memory);
    EXPECT_EQ(lookup(*texture, {0.375f, 0.5f}), lookup(*texture, {2.375f, 0.5f}));
    EXPECT_EQ(lookup(*texture, {0.375f, 0.5f}), lookup(*texture, {-0.625f, 0.5f}));
    // Between the last and first texel the lookup wraps: halfway = (3 + 0) / 2.
    EXPECT_NEAR(lookup(*texture, {1.0f, 0.5f}).r, 1.5f, 1e-6);
}

TEST(ImageTexture, BadFilesNameTheFile) {
    const ColourSystem colours("", "ACEScg");
    const auto missing = temp_dir() / "missing.png";
    try {
        ImageTexture::load(missing, "", colours, memory);
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("missing.png"), std::string::npos) << error.what();
    }
    const auto path = write_image<float>("nan.exr", 1, 1, {NAN, 0, 0});
    EXPECT_THROW(ImageTexture::load(path, "", colours, memory), InputError);
    EXPECT_THROW(ImageTexture::load(write_image<float>("ok.exr", 1, 1, {0, 0, 0}),
                                    "no_such_space", colours, memory),
                 InputError);
}

// The texture fuzzer's first finding (tests/fuzz/seeds/texture/truncated-png-oiio-leak): a PNG cut off after its
// header makes libpng fail inside OpenImageIO's read callback. It must be a clear error, never a crash. (OIIO 2.4
// leaks a string on this path, which is why the texture fuzzer runs without leak detection.)
TEST(ImageTexture, TruncatedPngIsAnInputErrorNamingTheFile) {
    const ColourSystem colours("", "ACEScg");
    const auto whole = write_image<std::uint8_t>("whole.png", 64, 64,
                                                 std::vector<std::uint8_t>(64 * 64 * 3, 200));
    const auto truncated = temp_dir() / "truncated.png";
    std::filesystem::copy_file(whole, truncated, std::filesystem::copy_options::overwrite_existing);
    std::filesystem::resize_file(truncated, 60);  // signature, IHDR and a few bytes of the next chunk
    const std::string message = load_error(truncated, colours);
    EXPECT_NE(message.find("truncated.png"), std::string::npos) << message;
}

// The texture fuzzer's second finding (tests/fuzz/seeds/texture/exr-attribute-claims-335mb): OpenEXR 3.1 trusts an
// attribute's declared size, so a 3 kB file claiming a 335 MB string took 18 s and 450 MB before failing. The
// header is checked first: an attribute larger than the rest of the file is an error naming it, at once.
TEST(ImageTexture, ExrAttributeLargerThanTheFileIsRefusedBeforeOpenExrReadsIt) {
    const ColourSystem colours("", "ACEScg");
    const auto path = write_image<float>("claims.exr", 2, 2, std::vector<float>(12, 0.5f));
    ASSERT_NO_THROW(ImageTexture::load(path, "", colours, memory));  // intact, it loads
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    // The first attribute: name and type (NUL-terminated) after the 8-byte magic and version, then its size.
    const std::size_t type_start = bytes.find('\0', 8) + 1;
    const std::string name = bytes.substr(8, type_start - 1 - 8);
    const std::size_t size_at = bytes.find('\0', type_start) + 1;
    const std::uint32_t claimed = 335'544'551;
    for (int i = 0; i < 4; ++i) bytes[size_at + std::size_t(i)] = char(claimed >> (8 * i) & 0xFF);
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
    const std::string message = load_error(path, colours);
    EXPECT_NE(message.find("claims.exr"), std::string::npos) << message;
    EXPECT_NE(message.find("attribute \"" + name + "\" claims 335544551 bytes"), std::string::npos) << message;
}

// PNG chunk checksum (CRC-32, ISO 3309), to forge a header that libpng accepts.
std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (const unsigned char b : bytes) {
        crc ^= b;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

std::string big_endian(std::uint32_t v) {
    return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

// A PNG of 65 bytes whose header claims 100000x100000 RGB pixels (120 GB as floats, 30 GB as stored).
TEST(ImageTexture, TinyFileClaimingAHugeImageIsRefusedFromItsHeaderBeforeAnyAllocation) {
    const std::string ihdr = "IHDR" + big_endian(100000) + big_endian(100000) + std::string("\x08\x02\x00\x00\x00", 5);
    const std::string idat = "IDAT" + std::string("\x78\x9c\x03\x00\x00\x00\x00\x01", 8);  // an empty zlib stream
    const std::string iend = "IEND";
    const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + big_endian(13) + ihdr + big_endian(crc32(ihdr)) +
                            big_endian(8) + idat + big_endian(crc32(idat)) + big_endian(0) + iend +
                            big_endian(crc32(iend));
    const testing::TemporaryDirectory dir("texture");
    const auto path = dir.write("huge.png", png);
    const ColourSystem colours("", "ACEScg");
    MemoryBudget budget(std::uint64_t(8) << 30);
    const std::string message = load_error(path, colours, budget);
    EXPECT_NE(message.find("huge.png"), std::string::npos) << message;
    EXPECT_NE(message.find("100000x100000"), std::string::npos) << message;
    EXPECT_NE(message.find("needs about 180 GB"), std::string::npos) << message;
    EXPECT_LE(budget.charged_bytes(), kImageModuleResidentBytes);  // at most the module, if this test loaded it
}

// The mip levels are charged with the image, from its header: a budget that holds the image alone refuses it with
// its levels before any pixel is read, and charges nothing.
TEST(ImageTexture, ReducedLevelsAreChargedBeforeTheImageIsRead) {
    const ColourSystem colours("", "ACEScg");
    const auto path = write_image<float>("levels.exr", 64, 64, std::vector<float>(64 * 64 * 3, 0.5f));
    ImageTexture::load(path, "", colours, memory);  // the image module is loaded (and charged) once, here
    MemoryBudget measure;
    ImageTexture::load(path, "", colours, measure);
    const std::uint64_t image_alone = measure.charged_bytes();
    const std::uint64_t levels = MipPyramid::reduced_texel_count(64, 64) * 3 * sizeof(float);
    ASSERT_GT(levels, 16000u);
    MemoryBudget budget(image_alone + levels / 2);
    EXPECT_NO_THROW(ImageTexture::load(path, "", colours, budget));
    MemoryBudget tight(image_alone + levels / 2);
    const std::string message = [&] {
        try {
            ImageTexture::load(path, "", colours, tight, {.mip_levels = true});
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    }();
    EXPECT_NE(message.find("the 64x64 image with its mip levels"), std::string::npos) << message;
    EXPECT_EQ(tight.charged_bytes(), 0u);
    MemoryBudget enough(image_alone + levels);
    EXPECT_EQ(ImageTexture::load(path, "", colours, enough, {.mip_levels = true})->pyramid().level_count(), 7);
}

TEST(ImageTexture, OneChannelOrDataAsStored) {
    const ColourSystem colours("", "ACEScg");
    const auto path = write_image<std::uint8_t>("channels.png", 1, 1, {51, 102, 255});
    const auto green = ImageTexture::load(path, "", colours, memory, {.content = ImageContent::Green});
    EXPECT_EQ(green->pyramid().channels(), 1);
    EXPECT_FLOAT_EQ(*green->pyramid().texel(0, 0, 0), 102.0f / 255);
    const auto data = ImageTexture::load(path, "", colours, memory, {.content = ImageContent::Data});
    EXPECT_FLOAT_EQ(data->texel(0, 0).r, 51.0f / 255);  // no sRGB decoding
    EXPECT_FLOAT_EQ(data->texel(0, 0).g, 102.0f / 255);
    EXPECT_EQ(data->colour_space(), "");
    try {
        ImageTexture::load(path, "", colours, memory, {.content = ImageContent::Alpha});
        ADD_FAILURE() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("channels.png: the image has no alpha channel"), std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace isotrace
