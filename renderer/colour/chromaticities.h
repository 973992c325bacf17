#pragma once
// CIE xy chromaticities of the working spaces the shipped config offers, for the EXR "chromaticities"
// attribute (so that other tools interpret our scene-linear files correctly).
#include <array>
#include <optional>
#include <string>

namespace isotrace {

// Red, green, blue and white xy pairs, in the order OpenEXR stores them. Empty for spaces without fixed
// primaries (Raw, log encodings, unknown names).
std::optional<std::array<float, 8>> chromaticities_of(const std::string& canonical_space_name);

}  // namespace isotrace
