#pragma once
// Reading any image file OpenImageIO can read, for isotrace diff. The one place image comparison touches OIIO,
// so that it can move to the shared image reader without touching the metrics.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace isotrace {

struct ImageFile {
    int width = 0, height = 0;
    std::vector<std::string> channels;
    std::vector<float> pixels;  // interleaved, width * height * channels.size()
    // Stored as integers (PNG, JPEG, 8/16-bit TIFF): display-referred, sRGB-encoded values in [0, 1]. Otherwise
    // (EXR, HDR, float TIFF): scene-linear.
    bool display_referred = false;
    std::vector<std::pair<std::string, std::string>> metadata;  // every attribute as text
    // OpenEXR's "chromaticities" (red, green, blue, white xy) when the file has them.
    std::optional<std::array<float, 8>> chromaticities;
};

// The first subimage, all channels, as float. Throws InputError naming the file when it cannot be read.
ImageFile read_image_file(const std::string& path);

}  // namespace isotrace
