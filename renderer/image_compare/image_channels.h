#pragma once
// Picking the channels a comparison needs out of an image file, with errors that name the file and the channel.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "renderer/image_compare/image_file.h"
#include "renderer/image_compare/rgb_image.h"

namespace isotrace {

// Index of a channel by name, if present.
std::optional<std::size_t> find_channel(const ImageFile& file, const std::string& name);

// One channel per pixel; throws InputError naming `path` if missing.
std::vector<float> channel_plane(const ImageFile& file, const std::string& name, const std::string& path);

// Three named channels as an RGB image; throws InputError naming `path` and the missing channel.
RgbImage channels_as_rgb(const ImageFile& file, const std::array<std::string, 3>& names, const std::string& path);

// The colour of an image: its R, G, B channels, or a grey image's single Y channel (or its only channel) in all
// three. Throws InputError if there is neither, or if a value is not finite.
RgbImage colour_of(const ImageFile& file, const std::string& path);

// colour_of() of a scene-linear image in linear sRGB: converted from the primaries its chromaticities attribute
// names (none: taken as linear sRGB already). Throws InputError for degenerate chromaticities.
RgbImage linear_srgb_colour_of(const ImageFile& file, const std::string& path);

}  // namespace isotrace
