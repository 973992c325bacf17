#pragma once
// An RGB image read by read_image_file (any format OpenImageIO reads) and converted to the working space once,
// at load time, then looked up with bilinear filtering and repeat wrapping. uv (0, 0) is the image's bottom-left
// corner.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "renderer/math/rgb.h"

namespace isotrace {

class ColourSystem;
class MemoryBudget;

// Memory that a user of a texture allocates for its own set-up from the texture's size (the environment light's
// sampling distribution), charged with the texture before any pixel is read.
struct TextureSetUpMemory {
    std::uint64_t per_texel = 0, per_row = 0;
};

class ImageTexture {
public:
    // `colour_space` empty: "srgb_texture" for integer pixel formats (8/16-bit PNG, JPEG, TIFF), the working
    // space for floating-point formats (EXR, HDR). The memory loading needs at its peak (the decoder's, the
    // texture's and `set_up`), known from the header, is charged to `memory` before any pixel is read. Throws
    // InputError naming the file on any read problem.
    static std::shared_ptr<const ImageTexture> load(const std::filesystem::path& path, const std::string& colour_space,
                                                    const ColourSystem& colours, MemoryBudget& memory,
                                                    const TextureSetUpMemory& set_up = {});

    Rgb lookup(std::array<float, 2> uv) const;
    // One texel in the working space; row y = 0 is the top of the image; x and y wrap around (repeat).
    Rgb texel(int x, int y) const;
    int width() const { return width_; }
    int height() const { return height_; }
    const std::string& colour_space() const { return colour_space_; }

private:
    ImageTexture(int width, int height, std::vector<float> rgb, std::string colour_space);

    int width_, height_;
    std::vector<float> rgb_;  // working space, row 0 = top of the image
    std::string colour_space_;
};

}  // namespace isotrace
