#pragma once
// An image file as isotrace diff compares it: read with read_image_file (any format the image module reads).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "renderer/core/memory_budget.h"
#include "renderer/image/image_metadata.h"

namespace isotrace {

struct ImageFile {
    int width = 0, height = 0;
    std::vector<std::string> channels;
    std::vector<float> pixels;  // interleaved, width * height * channels.size()
    // Stored as integers (PNG, JPEG, 8/16-bit TIFF): display-referred, sRGB-encoded values in [0, 1]. Otherwise
    // (EXR, HDR, float TIFF): scene-linear.
    bool display_referred = false;
    ImageMetadata metadata;
    // OpenEXR's "chromaticities" (red, green, blue, white xy) when the file has them.
    std::optional<std::array<float, 8>> chromaticities;
};

// The first subimage, all channels, as float. Decoding and `work_bytes_per_pixel` more (what the comparison will
// take) are charged to `memory` before any pixel is read. Throws InputError naming the file when it cannot be read
// or does not fit.
ImageFile read_image_for_comparison(const std::string& path, MemoryBudget& memory,
                                    std::uint64_t work_bytes_per_pixel = 0);

}  // namespace isotrace
