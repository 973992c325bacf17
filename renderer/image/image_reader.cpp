#include "renderer/image/image_reader.h"

#include "renderer/core/input_file.h"

#include "renderer/core/input_error.h"
#include "renderer/image/exr_header_check.h"

namespace isotrace {

DecodedImage read_image_file(const std::filesystem::path& path, const BeforePixels& before_pixels) {
    require_regular_input(path);  // a FIFO would block the decoder, a device stream into it
    check_exr_header_sizes(path);  // before OpenEXR trusts the sizes a few bytes of header declare
    DecodedImage image;
    const std::string problem = image_codec().decode(path, before_pixels, image);
    if (!problem.empty()) throw InputError({path.string(), 0, 0}, "", problem);
    return image;
}

}  // namespace isotrace
