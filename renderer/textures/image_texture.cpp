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

}  // namespace

ImageTexture::ImageTexture(int width, int height, std::vector<float> rgb, std::string colour_space)
    : width_(width), height_(height), rgb_(std::move(rgb)), colour_space_(std::move(colour_space)) {}

std::shared_ptr<const ImageTexture> ImageTexture::load(const std::filesystem::path& path,
                                                       const std::string& colour_space, const ColourSystem& colours,
                                                       MemoryBudget& memory, const TextureSetUpMemory& set_up) {
    const auto fail = [&](const std::string& problem) -> InputError { return InputError({path.string(), 0, 0}, "", problem); };
    // A few bytes of header can claim any size: what decoding needs, the RGB copy kept (none when the decoded
    // pixels are RGB: they are kept) and the user's set-up.
    const auto charge = [&](const ImageHeader& header) {
        const std::uint64_t copy = header.channel_names.size() == 3 ? 0 : 3 * sizeof(float);
        const std::uint64_t texels = saturating_product(
            {std::uint64_t(header.width), std::uint64_t(header.height),
             decoding_bytes_per_pixel(header) + copy + set_up.per_texel});
        const std::uint64_t rows = saturating_product({std::uint64_t(header.height), set_up.per_row});
        memory.charge(saturating_sum({texels, rows}),
                      "the " + std::to_string(header.width) + "x" + std::to_string(header.height) + " image",
                      {path.string(), 0, 0});
    };
    charge_image_module(memory, path);
    DecodedImage image = read_image_file(path, charge);
    const ImageHeader& header = image.header;

    // Grey images are spread to RGB; alpha and extra channels are ignored.
    const std::size_t count = std::size_t(header.width) * std::size_t(header.height);
    const std::size_t channels = header.channel_names.size();
    std::vector<float> rgb;
    if (channels == 3) {
        rgb = std::move(image.pixels);
    } else {
        rgb.resize(count * 3);
        for (std::size_t i = 0; i < count; ++i)
            for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = image.pixels[i * channels + (channels >= 3 ? c : 0)];
        image.pixels = {};
    }

    const bool is_float = is_floating_point(header.file_type);
    const std::string space = !colour_space.empty() ? colour_space : (is_float ? colours.working_space() : "srgb_texture");
    if (!colours.has_colour_space(space)) throw fail("unknown colour space \"" + space + "\"");
    // In pieces: OpenColorIO converts through a buffer of four floats per pixel of the piece it is given.
    for (std::size_t first = 0; first < count; first += kColourConversionPixels)
        colours.to_working(rgb.data() + first * 3, std::min(kColourConversionPixels, count - first), 3, space);
    // Texels are light (environment maps) or colours: a negative one would subtract light from the image.
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        if (!std::isfinite(rgb[i])) throw fail("image contains NaN or infinite values");
        if (rgb[i] < 0)
            throw fail("texel (" + std::to_string(i / 3 % std::size_t(header.width)) + ", " +
                       std::to_string(i / 3 / std::size_t(header.width)) + ") is negative (" + std::to_string(rgb[i]) +
                       ") in the working space " + colours.working_space() +
                       "; texels must be >= 0 (a colour outside the working space's gamut turns negative)");
    }
    return std::shared_ptr<const ImageTexture>(new ImageTexture(header.width, header.height, std::move(rgb), space));
}

Rgb ImageTexture::texel(int x, int y) const {
    x %= width_;
    y %= height_;
    if (x < 0) x += width_;
    if (y < 0) y += height_;
    const float* p = rgb_.data() + (std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 3;
    return {p[0], p[1], p[2]};
}

Rgb ImageTexture::lookup(std::array<float, 2> uv) const {
    // Texel centres sit at half-integer coordinates; v runs up the image.
    const float x = uv[0] * float(width_) - 0.5f;
    const float y = (1.0f - uv[1]) * float(height_) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    const int x0 = int(fx), y0 = int(fy);
    return texel(x0, y0) * ((1 - tx) * (1 - ty)) + texel(x0 + 1, y0) * (tx * (1 - ty)) +
           texel(x0, y0 + 1) * ((1 - tx) * ty) + texel(x0 + 1, y0 + 1) * (tx * ty);
}

}  // namespace isotrace
