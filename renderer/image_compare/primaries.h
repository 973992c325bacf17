#pragma once
// Scene-linear RGB of any primaries to linear RGB with the sRGB (Rec. 709) primaries and D65 white, the space
// FLIP's colour pipeline and the Rec. 709 luminance weights assume. isotrace writes ACEScg by default and says so
// in the EXR "chromaticities" attribute; other renderers' EXRs without it are taken as linear sRGB.
#include <array>

#include "renderer/image_compare/rgb_image.h"
#include "renderer/math/transform.h"

namespace isotrace {

// OpenEXR's order: red x, y, green x, y, blue x, y, white x, y.
using Chromaticities = std::array<float, 8>;
constexpr Chromaticities kSrgbChromaticities = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};

// The linear map RGB (given primaries) -> XYZ -> white adapted to D65 with the Bradford transform -> linear sRGB,
// as a Transform without translation. Throws std::invalid_argument for degenerate chromaticities.
Transform to_linear_srgb(const Chromaticities& chromaticities);

// Applies a map from to_linear_srgb() to every pixel.
void convert_colours(RgbImage& image, const Transform& map);

}  // namespace isotrace
