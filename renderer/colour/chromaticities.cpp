#include "renderer/colour/chromaticities.h"

namespace isotrace {

std::optional<std::array<float, 8>> chromaticities_of(const std::string& name) {
    // ACES primaries and white from SMPTE ST 2065-1 / Academy S-2014-004; Rec.709 from ITU-R BT.709-6.
    if (name == "ACEScg") return std::array<float, 8>{0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f};
    if (name == "ACES2065-1")
        return std::array<float, 8>{0.7347f, 0.2653f, 0.0f, 1.0f, 0.0001f, -0.077f, 0.32168f, 0.33767f};
    if (name == "Linear Rec.709 (sRGB)")
        return std::array<float, 8>{0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
    return std::nullopt;
}

}  // namespace isotrace
