#include "renderer/image_compare/rgb_image.h"

#include <stdexcept>
#include <string>

namespace isotrace {

std::vector<float> luminance_plane(const RgbImage& image) {
    std::vector<float> plane(image.pixel_count());
    for (std::size_t i = 0; i < plane.size(); ++i) plane[i] = luminance(image.values.data() + 3 * i);
    return plane;
}

void require_same_size(const RgbImage& reference, const RgbImage& test) {
    if (reference.width != test.width || reference.height != test.height || reference.pixel_count() == 0)
        throw std::invalid_argument("images of different or zero size: " + std::to_string(reference.width) + "x" +
                                    std::to_string(reference.height) + " and " + std::to_string(test.width) + "x" +
                                    std::to_string(test.height));
}

}  // namespace isotrace
