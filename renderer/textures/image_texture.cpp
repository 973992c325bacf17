#include "renderer/textures/image_texture.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "renderer/colour/colour_system.h"
#include "renderer/core/input_error.h"
#include "renderer/core/memory_budget.h"
#include "renderer/image/image_reader.h"

namespace isotrace {
namespace {

constexpr std::size_t kColourConversionPixels = std::size_t(1) << 16;

bool is_rgb(ImageContent content) { return content == ImageContent::Colour || content == ImageContent::Data; }

int kept_channels(ImageContent content) { return is_rgb(content) ? 3 : 1; }

// The decoded pixels are kept as they are when they already hold what is kept.
bool keeps_decoded_pixels(const ImageHeader& header, ImageContent content) {
    return is_rgb(content) ? header.channel_names.size() == 3 : header.channel_names.size() == 1 && content != ImageContent::Alpha;
}

// Level 0 of the texture from the decoded pixels: RGB (grey spread to RGB; alpha and extra channels ignored) or
// the one channel asked for.
std::vector<float> kept_pixels(DecodedImage& image, ImageContent content, const std::filesystem::path& path) {
    const ImageHeader& header = image.header;
    if (keeps_decoded_pixels(header, content)) return std::move(image.pixels);
    const std::size_t count = std::size_t(header.width) * std::size_t(header.height);
    const std::size_t channels = header.channel_names.size();
    const auto rgb_channel = [&](std::size_t c) { return channels >= 3 ? c : 0; };
    std::vector<float> kept(count * std::size_t(kept_channels(content)));
    const float* in = image.pixels.data();
    if (is_rgb(content)) {
        for (std::size_t i = 0; i < count; ++i)
            for (std::size_t c = 0; c < 3; ++c) kept[i * 3 + c] = in[i * channels + rgb_channel(c)];
    } else if (content == ImageContent::Luminance) {
        for (std::size_t i = 0; i < count; ++i)
            kept[i] = 0.2126f * in[i * channels + rgb_channel(0)] + 0.7152f * in[i * channels + rgb_channel(1)] +
                      0.0722f * in[i * channels + rgb_channel(2)];
    } else {
        std::size_t channel = 0;
        if (content == ImageContent::Alpha) {
            if (header.alpha_channel < 0)
                throw InputError({path.string(), 0, 0}, "", "the image has no alpha channel");
            channel = std::size_t(header.alpha_channel);
        } else {
            channel = rgb_channel(content == ImageContent::Red ? 0 : content == ImageContent::Green ? 1 : 2);
        }
        for (std::size_t i = 0; i < count; ++i) kept[i] = in[i * channels + channel];
    }
    image.pixels = {};
    return kept;
}

}  // namespace

std::shared_ptr<const ImageTexture> ImageTexture::load(const std::filesystem::path& path,
                                                       const std::string& colour_space, const ColourSystem& colours,
                                                       MemoryBudget& memory, const ImageLoadOptions& options) {
    const auto fail = [&](const std::string& problem) -> InputError { return InputError({path.string(), 0, 0}, "", problem); };
    const int channels = kept_channels(options.content);
    // A few bytes of header can claim any size: what decoding needs, the copy kept (none when the decoded pixels
    // are kept as they are), its reduced levels and the user's set-up.
    const auto charge = [&](const ImageHeader& header) {
        const std::uint64_t texel_bytes = std::uint64_t(channels) * sizeof(float);
        const std::uint64_t copy = keeps_decoded_pixels(header, options.content) ? 0 : texel_bytes;
        const std::uint64_t texels = saturating_product(
            {std::uint64_t(header.width), std::uint64_t(header.height),
             decoding_bytes_per_pixel(header) + copy + options.set_up.per_texel});
        const std::uint64_t levels =
            options.mip_levels
                ? saturating_product({MipPyramid::reduced_texel_count(header.width, header.height), texel_bytes})
                : 0;
        const std::uint64_t rows = saturating_product({std::uint64_t(header.height), options.set_up.per_row});
        memory.charge(saturating_sum({texels, levels, rows}),
                      "the " + std::to_string(header.width) + "x" + std::to_string(header.height) + " image" +
                          (options.mip_levels ? " with its mip levels" : ""),
                      {path.string(), 0, 0});
    };
    charge_image_module(memory, path);
    DecodedImage image = read_image_file(path, charge);
    const int width = image.header.width, height = image.header.height;
    const bool is_float = is_floating_point(image.header.file_type);
    std::vector<float> pixels = kept_pixels(image, options.content, path);

    std::string space;
    if (options.content == ImageContent::Colour) {
        space = !colour_space.empty() ? colour_space : (is_float ? colours.working_space() : "srgb_texture");
        if (!colours.has_colour_space(space)) throw fail("unknown colour space \"" + space + "\"");
        // In pieces: OpenColorIO converts through a buffer of four floats per pixel of the piece it is given.
        const std::size_t count = pixels.size() / 3;
        for (std::size_t first = 0; first < count; first += kColourConversionPixels)
            colours.to_working(pixels.data() + first * 3, std::min(kColourConversionPixels, count - first), 3, space);
    }
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        if (!std::isfinite(pixels[i])) throw fail("image contains NaN or infinite values");
        // Colour texels are light (environment maps) or colours: a negative one would subtract light.
        if (options.content == ImageContent::Colour && pixels[i] < 0)
            throw fail("texel (" + std::to_string(i / 3 % std::size_t(width)) + ", " +
                       std::to_string(i / 3 / std::size_t(width)) + ") is negative (" + std::to_string(pixels[i]) +
                       ") in the working space " + colours.working_space() +
                       "; texels must be >= 0 (a colour outside the working space's gamut turns negative)");
    }
    return std::shared_ptr<const ImageTexture>(
        new ImageTexture(MipPyramid(width, height, channels, std::move(pixels), options.mip_levels), std::move(space)));
}

}  // namespace isotrace
