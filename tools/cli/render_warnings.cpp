#include "tools/cli/render_warnings.h"

#include <algorithm>
#include <cmath>

namespace isotrace::cli {

BeautyCheck check_beauty(const ImageBuffer& image) {
    BeautyCheck check;
    std::vector<std::size_t> beauty;
    for (const char* name : {"R", "G", "B"}) {
        const auto found = std::find(image.channels.begin(), image.channels.end(), name);
        if (found != image.channels.end()) beauty.push_back(std::size_t(found - image.channels.begin()));
    }
    const std::size_t stride = image.channels.size();
    check.pixels = std::uint64_t(image.width) * std::uint64_t(image.height);
    if (beauty.size() != 3) {  // no beauty to judge
        check.all_black = false;
        return check;
    }
    for (std::size_t start = 0; start + stride <= image.pixels.size(); start += stride) {
        bool finite = true, black = true;
        for (std::size_t channel : beauty) {
            const float value = image.pixels[start + channel];
            finite = finite && std::isfinite(value);
            black = black && value == 0;
        }
        if (!finite) ++check.non_finite_pixels;
        else if (!black) check.all_black = false;
    }
    return check;
}

std::string light_left_out_warning(const LoadedScene& scene) {
    const std::vector<std::string> left_out = scene.integrator->light_left_out(*scene.scene);
    if (left_out.empty()) return "";
    std::string list;
    for (std::size_t i = 0; i < left_out.size(); ++i)
        list += (i == 0 ? "" : i + 1 == left_out.size() ? "; and " : "; ") + left_out[i];
    return "the " + scene.integrator_type + " integrator leaves out " + list +
           "; for all of the scene's light use \"integrator\": {\"type\": \"path\"}";
}

std::vector<std::string> beauty_warnings(const BeautyCheck& check) {
    std::vector<std::string> warnings;
    if (check.non_finite_pixels > 0)
        warnings.push_back(std::to_string(check.non_finite_pixels) + " of " + std::to_string(check.pixels) +
                           " pixels are NaN or infinite");
    if (check.all_black && check.pixels > check.non_finite_pixels)
        warnings.push_back("the image is black everywhere (no light reaches the camera: are there lights, and do "
                           "they face the scene?)");
    return warnings;
}

}  // namespace isotrace::cli
