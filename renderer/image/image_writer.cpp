#include "renderer/image/image_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "renderer/colour/colour_system.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/input_error.h"
#include "renderer/core/lower_extension.h"
#include "renderer/image/image_codec.h"

namespace isotrace {
namespace {

// Shortest text that reads back as the same number (of the same type: a float prints as "0.708", not "0.70800000429").
template <class Real>
std::string format_shortest(Real v) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
}

// PNG keeps string attributes only (as text chunks); JPEG and TIFF keep only standard tags. So display images
// carry every entry as text, and all isotrace:* entries once more in ImageDescription ("key=value; ..."), which
// all three formats keep: a partial render can always be told from a finished one.
ImageEncoding display_encoding(int width, int height, std::vector<std::string> channel_names,
                               const ImageMetadata& metadata) {
    ImageEncoding encoding;
    encoding.width = width;
    encoding.height = height;
    encoding.channel_names = std::move(channel_names);
    encoding.memory_type = encoding.file_type = PixelType::UInt8;
    std::string description;
    for (const auto& [name, value] : metadata.entries) {
        std::string text;
        if (const auto* s = std::get_if<std::string>(&value)) text = *s;
        else if (const auto* real = std::get_if<double>(&value)) text = format_shortest(*real);
        else if (const auto* integer = std::get_if<std::int64_t>(&value)) text = std::to_string(*integer);
        else
            for (float f : std::get<std::vector<float>>(value)) text += (text.empty() ? "" : " ") + format_shortest(f);
        encoding.metadata.set(name, text);
        if (name.rfind("isotrace:", 0) == 0) description += (description.empty() ? "" : "; ") + name + "=" + text;
    }
    if (!description.empty()) encoding.metadata.set("ImageDescription", description);
    return encoding;
}

}  // namespace

ImageKind image_kind_for(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    if (ext == ".exr") return ImageKind::Exr;
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".tif" || ext == ".tiff") return ImageKind::Display;
    throw InputError({}, "output", "cannot tell the image format of \"" + path.string() +
                                       "\": use .exr (scene-linear, all channels) or .png/.jpg/.tif (display)");
}

// Encodes first and hands the bytes to write_file_atomically: the encoders never write the output, so a full
// disk is one checked write() and not an error deep inside libpng/libjpeg (libjpeg calls exit() on a failed
// write; libpng wrote a truncated file and reported success).
void write_image_file(const std::filesystem::path& path, const ImageEncoding& image) {
    const std::vector<unsigned char> encoded = image_encoder_for(path).encode(path, image);
    write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

void write_exr(const std::filesystem::path& path, const ImageBuffer& image, const ImageWindow& window,
               bool half_float, const ImageMetadata& metadata) {
    ImageEncoding encoding;
    encoding.width = image.width;
    encoding.height = image.height;
    encoding.channel_names = image.channels;
    encoding.pixels = image.pixels.data();
    encoding.file_type = half_float ? PixelType::Half : PixelType::Float;
    encoding.alpha_channel = image.channels.size() > 3 && image.channels[3] == "A" ? 3 : -1;  // a lone Z has none
    encoding.x = window.x;
    encoding.y = window.y;
    encoding.full_width = window.full.width;
    encoding.full_height = window.full.height;
    // Ids and counts must stay exact integers: keep them 32-bit float even in a half file.
    if (half_float)
        for (const std::string& name : image.channels)
            encoding.channel_file_types.push_back(name == "objectId" || name == "primitiveId" ||
                                                          name == "sampleCount" || name == "Z" ||
                                                          name.rfind("P.", 0) == 0
                                                      ? PixelType::Float
                                                      : PixelType::Half);
    encoding.compression = "zip";
    encoding.metadata = metadata;
    write_image_file(path, encoding);
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
    ImageEncoding encoding = display_encoding(image.width, image.height, {"R", "G", "B"}, metadata);
    encoding.metadata.set("oiio:ColorSpace", std::string("sRGB"));
    encoding.pixels = bytes.data();
    write_image_file(path, encoding);
}

namespace {

// 8-bit pixels written as they are, without colour transform, atomically.
void write_8bit_image(const std::filesystem::path& path, int width, int height, const std::vector<std::string>& channels,
                      const std::vector<std::uint8_t>& pixels, const ImageMetadata& metadata) {
    if (pixels.size() != std::size_t(width) * std::size_t(height) * channels.size())
        throw std::logic_error("write_8bit_image: pixel count does not match the size");
    ImageEncoding encoding = display_encoding(width, height, channels, metadata);
    encoding.pixels = pixels.data();
    write_image_file(path, encoding);
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
