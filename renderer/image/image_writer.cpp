#include "renderer/image/image_writer.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
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

void write_with_oiio(const std::filesystem::path& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc pixel_type,
                     const void* pixels) {
    write_atomically(path, [&](const std::filesystem::path& temporary) {
        auto out = OIIO::ImageOutput::create(temporary.string());
        if (!out) throw std::runtime_error("cannot write " + path.string() + ": " + OIIO::geterror());
        if (!out->open(temporary.string(), spec) || !out->write_image(pixel_type, pixels) || !out->close())
            throw std::runtime_error("cannot write " + path.string() + ": " + out->geterror());
    });
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
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    apply_metadata(spec, metadata);
    spec.attribute("oiio:ColorSpace", "sRGB");
    write_with_oiio(path, spec, OIIO::TypeDesc::UINT8, bytes.data());
}

void write_grey8_image(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& pixels,
                       const ImageMetadata& metadata) {
    if (pixels.size() != std::size_t(width) * std::size_t(height))
        throw std::logic_error("write_grey8_image: pixel count does not match the size");
    OIIO::ImageSpec spec(width, height, 1, OIIO::TypeDesc::UINT8);
    spec.channelnames = {"Y"};
    apply_metadata(spec, metadata);
    write_with_oiio(path, spec, OIIO::TypeDesc::UINT8, pixels.data());
}

}  // namespace isotrace
