#include "renderer/image_compare/image_file.h"

#include <limits>
#include <variant>

#include "renderer/core/input_error.h"
#include "renderer/image/image_reader.h"

namespace isotrace {

ImageFile read_image_for_comparison(const std::string& path, MemoryBudget& memory, std::uint64_t work_bytes_per_pixel) {
    charge_image_module(memory, path);
    DecodedImage decoded = read_image_file(path, [&](const ImageHeader& header) {
        const std::size_t count =
            std::size_t(header.width) * std::size_t(header.height) * header.channel_names.size();
        if (count > std::size_t(std::numeric_limits<int>::max()))
            throw InputError({path, 0, 0}, "", "the image is too large to compare");
        memory.charge(saturating_product({std::uint64_t(header.width), std::uint64_t(header.height),
                                          decoding_bytes_per_pixel(header) + work_bytes_per_pixel}),
                      "comparing the " + std::to_string(header.width) + "x" + std::to_string(header.height) + " image",
                      {path, 0, 0});
    });
    ImageFile image;
    image.width = decoded.header.width;
    image.height = decoded.header.height;
    image.channels = std::move(decoded.header.channel_names);
    image.pixels = std::move(decoded.pixels);
    image.display_referred = !is_floating_point(decoded.header.file_type);
    image.metadata = std::move(decoded.header.metadata);
    if (const ImageMetadata::Value* xy = image.metadata.find("chromaticities")) {
        const auto* floats = std::get_if<std::vector<float>>(xy);
        if (floats && floats->size() == 8) {
            std::array<float, 8> chromaticities{};
            std::copy(floats->begin(), floats->end(), chromaticities.begin());
            image.chromaticities = chromaticities;
        }
    }
    return image;
}

}  // namespace isotrace
