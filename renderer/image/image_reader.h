#pragma once
// Reading image files: any format OpenImageIO reads (EXR, PNG, JPEG, TIFF, HDR, ...), every channel as float,
// with the header's windows, channel names and types and all metadata. The image module is loaded on the first
// call (see image_codec.h).
#include <cstdint>
#include <filesystem>

#include "renderer/core/memory_budget.h"
#include "renderer/image/image_codec.h"

namespace isotrace {

// Reads the first 2-D image of `path`. `before_pixels` (optional) sees the header before the pixels are allocated
// and may throw to refuse the image (e.g. MemoryBudget::charge for decoding_bytes_per_pixel). The file must be in
// the format its extension names (image_signature.h), and OpenEXR headers are checked first (exr_header_check.h).
// Throws InputError naming the file when it cannot be opened or read, is not 2-D or has no channels;
// std::runtime_error when the image module cannot be loaded.
DecodedImage read_image_file(const std::filesystem::path& path, const BeforePixels& before_pixels = {});

// Resident bytes per pixel that read_image_file needs at its peak for an image with this header: the float pixels
// it returns and the decoder's own buffers (measured per format, docs/reliability.md).
std::uint64_t decoding_bytes_per_pixel(const ImageHeader& header);

// Charges the image module's libraries (kImageModuleResidentBytes) to `memory` unless the module is loaded already,
// for the first image read under a budget; `file` is named if that does not fit.
void charge_image_module(MemoryBudget& memory, const std::filesystem::path& file);

}  // namespace isotrace
