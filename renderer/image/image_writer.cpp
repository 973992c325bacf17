#include "renderer/image/image_writer.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <stdlib.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "renderer/colour/colour_system.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// Shortest text that reads back as the same number (of the same type: a float prints as "0.708", not "0.70800000429").
template <class Real>
std::string format_shortest(Real v) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
}

void apply_metadata(OIIO::ImageSpec& spec, const ImageMetadata& metadata) {
    for (const auto& [name, value] : metadata.entries) {
        if (const auto* text = std::get_if<std::string>(&value)) spec.attribute(name, *text);
        else if (const auto* real = std::get_if<double>(&value)) spec.attribute(name, float(*real));
        else if (const auto* integer = std::get_if<std::int64_t>(&value)) {
            // EXR integer attributes are 32-bit: write larger values as text rather than wrapping them.
            if (*integer >= std::numeric_limits<int>::min() && *integer <= std::numeric_limits<int>::max())
                spec.attribute(name, int(*integer));
            else
                spec.attribute(name, std::to_string(*integer));
        }
        else {
            const auto& floats = std::get<std::vector<float>>(value);
            spec.attribute(name, OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, int(floats.size())), floats.data());
        }
    }
}

// Encoded bytes of one image. Writers that take an I/O proxy encode in memory; OIIO 2.4's TIFF writer does not
// work through one (the file loses its size tags), so TIFF goes to a file in a fresh private directory (mode
// 0700: nothing can be planted there) and is read back.
std::vector<unsigned char> encode(OIIO::ImageOutput& out, const std::filesystem::path& path, const OIIO::ImageSpec& spec,
                                  OIIO::TypeDesc pixel_type, const void* pixels) {
    const auto fail = [&] { throw std::runtime_error("cannot write " + path.string() + ": " + out.geterror()); };
    if (std::string(out.format_name()) != "tiff") {
        std::vector<unsigned char> bytes;
        OIIO::Filesystem::IOVecOutput memory(bytes);
        OIIO::ImageSpec proxied = spec;
        void* proxy = &memory;
        proxied.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        if (!out.open(path.string(), proxied) || !out.write_image(pixel_type, pixels) || !out.close()) fail();
        return bytes;
    }
    std::string directory = (std::filesystem::temp_directory_path() / "isotrace-encode-XXXXXX").string();
    if (!::mkdtemp(directory.data()))
        throw std::runtime_error("cannot write " + path.string() + ": no private temporary directory: " +
                                 std::strerror(errno));
    const std::filesystem::path file = std::filesystem::path(directory) / ("image" + path.extension().string());
    std::vector<unsigned char> bytes;
    const bool written = out.open(file.string(), spec) && out.write_image(pixel_type, pixels) && out.close();
    if (written) {
        std::ifstream in(file, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::error_code ignored;
    std::filesystem::remove_all(directory, ignored);
    if (!written) fail();
    return bytes;
}

// Encodes first and hands the bytes to write_file_atomically: the encoders never write the output, so a full
// disk is one checked write() and not an error deep inside libpng/libjpeg (libjpeg calls exit() on a failed
// write; libpng wrote a truncated file and reported success).
void write_with_oiio(const std::filesystem::path& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc pixel_type,
                     const void* pixels) {
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) throw std::runtime_error("cannot write " + path.string() + ": " + OIIO::geterror());
    const std::vector<unsigned char> encoded = encode(*out, path, spec, pixel_type, pixels);
    write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

// PNG keeps string attributes only (as text chunks); JPEG and TIFF keep only standard tags. So display images
// carry every entry as text, and all isotrace:* entries once more in ImageDescription ("key=value; ..."), which
// all three formats keep: a partial render can always be told from a finished one.
OIIO::ImageSpec display_spec(int width, int height, int channels, const ImageMetadata& metadata) {
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
    std::string description;
    for (const auto& [name, value] : metadata.entries) {
        std::string text;
        if (const auto* s = std::get_if<std::string>(&value)) text = *s;
        else if (const auto* real = std::get_if<double>(&value)) text = format_shortest(*real);
        else if (const auto* integer = std::get_if<std::int64_t>(&value)) text = std::to_string(*integer);
        else
            for (float f : std::get<std::vector<float>>(value)) text += (text.empty() ? "" : " ") + format_shortest(f);
        spec.attribute(name, text);
        if (name.rfind("isotrace:", 0) == 0) description += (description.empty() ? "" : "; ") + name + "=" + text;
    }
    if (!description.empty()) spec.attribute("ImageDescription", description);
    return spec;
}

}  // namespace

ImageKind image_kind_for(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    if (ext == ".exr") return ImageKind::Exr;
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".tif" || ext == ".tiff") return ImageKind::Display;
    throw InputError({}, "output", "cannot tell the image format of \"" + path.string() +
                                       "\": use .exr (scene-linear, all channels) or .png/.jpg/.tif (display)");
}

void write_exr(const std::filesystem::path& path, const ImageBuffer& image, const ImageWindow& window,
               bool half_float, const ImageMetadata& metadata) {
    const int channel_count = int(image.channels.size());
    OIIO::ImageSpec spec(image.width, image.height, channel_count, half_float ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
    spec.channelnames = image.channels;
    spec.alpha_channel = image.channels.size() > 3 && image.channels[3] == "A" ? 3 : -1;  // a lone Z has none
    spec.x = window.x;
    spec.y = window.y;
    spec.full_x = 0;
    spec.full_y = 0;
    spec.full_width = window.full.width;
    spec.full_height = window.full.height;
    // Ids and counts must stay exact integers: keep them 32-bit float even in a half file.
    if (half_float) {
        spec.channelformats.assign(std::size_t(channel_count), OIIO::TypeDesc::HALF);
        for (int c = 0; c < channel_count; ++c) {
            const std::string& name = image.channels[std::size_t(c)];
            if (name == "objectId" || name == "primitiveId" || name == "sampleCount" || name == "Z" ||
                name.rfind("P.", 0) == 0)
                spec.channelformats[std::size_t(c)] = OIIO::TypeDesc::FLOAT;
        }
    }
    spec.attribute("compression", "zip");
    apply_metadata(spec, metadata);
    write_with_oiio(path, spec, OIIO::TypeDesc::FLOAT, image.pixels.data());
}

void write_display_image(const std::filesystem::path& path, const ImageBuffer& image, const ColourSystem& colours,
                         const std::string& display, const std::string& view, const ImageMetadata& metadata) {
    const std::size_t pixel_count = std::size_t(image.width) * std::size_t(image.height);
    const std::size_t stride = image.channels.size();
    std::vector<float> rgb(pixel_count * 3);
    for (std::size_t i = 0; i < pixel_count; ++i)
        for (int c = 0; c < 3; ++c) rgb[i * 3 + std::size_t(c)] = image.pixels[i * stride + std::size_t(c)];
    colours.to_display(rgb.data(), pixel_count, 3, display, view);
    std::vector<unsigned char> bytes(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        const float v = std::isfinite(rgb[i]) ? std::clamp(rgb[i], 0.0f, 1.0f) : 0.0f;
        bytes[i] = static_cast<unsigned char>(std::lround(v * 255.0f));
    }
    OIIO::ImageSpec spec = display_spec(image.width, image.height, 3, metadata);
    spec.attribute("oiio:ColorSpace", "sRGB");
    write_with_oiio(path, spec, OIIO::TypeDesc::UINT8, bytes.data());
}

namespace {

// 8-bit pixels written as they are, without colour transform, atomically.
void write_8bit_image(const std::filesystem::path& path, int width, int height, const std::vector<std::string>& channels,
                      const std::vector<std::uint8_t>& pixels, const ImageMetadata& metadata) {
    if (pixels.size() != std::size_t(width) * std::size_t(height) * channels.size())
        throw std::logic_error("write_8bit_image: pixel count does not match the size");
    OIIO::ImageSpec spec = display_spec(width, height, int(channels.size()), metadata);
    spec.channelnames = channels;
    write_with_oiio(path, spec, OIIO::TypeDesc::UINT8, pixels.data());
}

}  // namespace

void write_grey8_image(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& pixels,
                       const ImageMetadata& metadata) {
    write_8bit_image(path, width, height, {"Y"}, pixels, metadata);
}

void write_rgb8_image(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& pixels,
                      const ImageMetadata& metadata) {
    write_8bit_image(path, width, height, {"R", "G", "B"}, pixels, metadata);
}

}  // namespace isotrace
