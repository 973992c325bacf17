#include "renderer/textures/image_texture.h"

#include <OpenImageIO/imageio.h>

#include <cmath>

#include "renderer/colour/colour_system.h"
#include "renderer/core/input_error.h"
#include "renderer/core/memory_budget.h"
#include "renderer/textures/exr_header_check.h"

namespace isotrace {

ImageTexture::ImageTexture(int width, int height, std::vector<float> rgb, std::string colour_space)
    : width_(width), height_(height), rgb_(std::move(rgb)), colour_space_(std::move(colour_space)) {}

std::shared_ptr<const ImageTexture> ImageTexture::load(const std::filesystem::path& path,
                                                       const std::string& colour_space, const ColourSystem& colours,
                                                       MemoryBudget& memory) {
    const auto fail = [&](const std::string& problem) -> InputError { return InputError({path.string(), 0, 0}, "", problem); };
    check_exr_header_sizes(path);  // before OpenEXR trusts the sizes a few bytes of header declare
    auto input = OIIO::ImageInput::open(path.string());
    if (!input) throw fail("cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.width < 1 || spec.height < 1 || spec.depth != 1) throw fail("not a 2-D image");
    if (spec.nchannels < 1) throw fail("image has no channels");
    // A few bytes of header can claim any size: the float pixels read plus the RGB copy kept.
    memory.charge(saturating_product({std::uint64_t(spec.width), std::uint64_t(spec.height),
                                      std::uint64_t(spec.nchannels) + 3, sizeof(float)}),
                  "the " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " image",
                  {path.string(), 0, 0});
    std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
        throw fail("cannot read pixels: " + input->geterror());
    input->close();

    // Grey images are spread to RGB; alpha and extra channels are ignored.
    const std::size_t count = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<float> rgb(count * 3);
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c)
            rgb[i * 3 + std::size_t(c)] = pixels[i * std::size_t(spec.nchannels) + std::size_t(spec.nchannels >= 3 ? c : 0)];

    const bool is_float = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF ||
                          spec.format.basetype == OIIO::TypeDesc::DOUBLE;
    const std::string space = !colour_space.empty() ? colour_space : (is_float ? colours.working_space() : "srgb_texture");
    if (!colours.has_colour_space(space)) throw fail("unknown colour space \"" + space + "\"");
    colours.to_working(rgb.data(), count, 3, space);
    for (float v : rgb)
        if (!std::isfinite(v)) throw fail("image contains NaN or infinite values");
    return std::shared_ptr<const ImageTexture>(new ImageTexture(spec.width, spec.height, std::move(rgb), space));
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
