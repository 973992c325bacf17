#pragma once
// Reading image files: any format OpenImageIO reads (EXR, PNG, JPEG, TIFF, HDR, ...), every channel as float,
// with the header's windows, channel names and types and all metadata. The image module is loaded on the first
// call (see image_codec.h).
#include <filesystem>

#include "renderer/image/image_codec.h"

namespace isotrace {

// Reads the first 2-D image of `path`. `before_pixels` (optional) sees the header before the pixels are allocated
// and may throw to refuse the image (e.g. MemoryBudget::charge for its size). OpenEXR headers are checked first
// (exr_header_check.h). Throws InputError naming the file when it cannot be opened or read, is not 2-D or has no
// channels; std::runtime_error when the image module cannot be loaded.
DecodedImage read_image_file(const std::filesystem::path& path, const BeforePixels& before_pixels = {});

}  // namespace isotrace
