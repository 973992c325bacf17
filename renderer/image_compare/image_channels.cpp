#include "renderer/image_compare/image_channels.h"

#include <algorithm>
#include <cmath>

#include "renderer/core/input_error.h"
#include "renderer/image_compare/primaries.h"

namespace isotrace {

std::optional<std::size_t> find_channel(const ImageFile& file, const std::string& name) {
    const auto found = std::find(file.channels.begin(), file.channels.end(), name);
    if (found == file.channels.end()) return std::nullopt;
    return std::size_t(found - file.channels.begin());
}

std::vector<float> channel_plane(const ImageFile& file, const std::string& name, const std::string& path) {
    const std::optional<std::size_t> index = find_channel(file, name);
    if (!index) {
        std::string list;
        for (const std::string& c : file.channels) list += (list.empty() ? "" : ", ") + c;
        throw InputError({path, 0, 0}, "", "no channel \"" + name + "\" (channels: " + list + ")");
    }
    const std::size_t stride = file.channels.size(), pixels = std::size_t(file.width) * std::size_t(file.height);
    std::vector<float> plane(pixels);
    for (std::size_t i = 0; i < pixels; ++i) plane[i] = file.pixels[i * stride + *index];
    return plane;
}

RgbImage channels_as_rgb(const ImageFile& file, const std::array<std::string, 3>& names, const std::string& path) {
    RgbImage image(file.width, file.height);
    for (std::size_t c = 0; c < 3; ++c) {
        const std::vector<float> plane = channel_plane(file, names[c], path);
        for (std::size_t i = 0; i < plane.size(); ++i) image.values[3 * i + c] = plane[i];
    }
    return image;
}

RgbImage colour_of(const ImageFile& file, const std::string& path) {
    RgbImage image;
    if (find_channel(file, "R") && find_channel(file, "G") && find_channel(file, "B")) {
        image = channels_as_rgb(file, {"R", "G", "B"}, path);
    } else if (find_channel(file, "Y") || file.channels.size() == 1) {
        const std::string grey = find_channel(file, "Y") ? "Y" : file.channels.front();
        image = channels_as_rgb(file, {grey, grey, grey}, path);
    } else {
        throw InputError({path, 0, 0}, "", "no colour channels: neither R, G, B nor a single grey channel");
    }
    for (std::size_t i = 0; i < image.values.size(); ++i)
        if (!std::isfinite(image.values[i]))
            throw InputError({path, 0, 0}, "",
                             "pixel " + std::to_string(i / 3 % std::size_t(image.width)) + "," +
                                 std::to_string(i / 3 / std::size_t(image.width)) + " has a value that is not finite (" +
                                 std::to_string(image.values[i]) + ")");
    return image;
}

RgbImage linear_srgb_colour_of(const ImageFile& file, const std::string& path) {
    RgbImage image = colour_of(file, path);
    if (!file.chromaticities) return image;
    try {
        convert_colours(image, to_linear_srgb(*file.chromaticities));
    } catch (const std::invalid_argument& error) {
        throw InputError({path, 0, 0}, "chromaticities", error.what());
    }
    return image;
}

}  // namespace isotrace
