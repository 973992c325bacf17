#pragma once
// An image read by read_image_file (any format OpenImageIO reads): its RGB converted to the working space once, at
// load time (colour images), or one channel or the RGB as stored (data), kept as a MipPyramid. uv (0, 0) is the
// image's bottom-left corner.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "renderer/math/rgb.h"
#include "renderer/textures/mip_pyramid.h"

namespace isotrace {

class ColourSystem;
class MemoryBudget;

// Memory that a user of a texture allocates for its own set-up from the texture's size (the environment light's
// sampling distribution), charged with the texture before any pixel is read.
struct TextureSetUpMemory {
    std::uint64_t per_texel = 0, per_row = 0;
};

// What is kept of a file's pixels.
enum class ImageContent {
    Colour,  // RGB converted from the image's colour space to the working space; texels must be >= 0
    Data,    // RGB as stored (normal maps)
    // One channel as stored, for scalar parameters. Grey images give their grey for r, g, b and luminance.
    Red,
    Green,
    Blue,
    Alpha,
    Luminance,  // Rec. 709 weights of the stored RGB
};

struct ImageLoadOptions {
    ImageContent content = ImageContent::Colour;
    bool mip_levels = false;  // build the reduced levels, for lookups with a footprint
    TextureSetUpMemory set_up{};
};

class ImageTexture {
public:
    // `colour_space` (colour images) empty: "srgb_texture" for integer pixel formats (8/16-bit PNG, JPEG, TIFF),
    // the working space for floating-point formats (EXR, HDR). The memory loading needs at its peak (the
    // decoder's, the texture's with its levels and `options.set_up`), known from the header, is charged to
    // `memory` before any pixel is read. Throws InputError naming the file on any read problem.
    static std::shared_ptr<const ImageTexture> load(const std::filesystem::path& path, const std::string& colour_space,
                                                    const ColourSystem& colours, MemoryBudget& memory,
                                                    const ImageLoadOptions& options = {});

    // One texel of an RGB texture; row y = 0 is the top of the image; x and y wrap around (repeat).
    Rgb texel(int x, int y) const {
        return to_rgb(pyramid_.texel(0, wrap_index(x, width(), WrapMode::Repeat), wrap_index(y, height(), WrapMode::Repeat)));
    }
    const MipPyramid& pyramid() const { return pyramid_; }
    int width() const { return pyramid_.width(); }
    int height() const { return pyramid_.height(); }
    // Colour images: the space they were converted from; empty for data.
    const std::string& colour_space() const { return colour_space_; }

    static Rgb to_rgb(const float* p) { return {p[0], p[1], p[2]}; }
    static Rgb to_rgb(const std::array<float, 3>& p) { return {p[0], p[1], p[2]}; }

private:
    ImageTexture(MipPyramid pyramid, std::string colour_space)
        : pyramid_(std::move(pyramid)), colour_space_(std::move(colour_space)) {}

    MipPyramid pyramid_;
    std::string colour_space_;
};

}  // namespace isotrace
