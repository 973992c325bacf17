#include "renderer/image/image_reader.h"

#include "renderer/core/input_error.h"
#include "renderer/core/input_file.h"
#include "renderer/image/exr_header_check.h"
#include "renderer/image/image_signature.h"
#include "renderer/image/png_chunk_check.h"

namespace isotrace {
namespace {

std::uint64_t stored_bytes(PixelType type) {
    switch (type) {
        case PixelType::UInt8: case PixelType::Int8: return 1;
        case PixelType::UInt16: case PixelType::Int16: case PixelType::Half: return 2;
        case PixelType::UInt32: case PixelType::Int32: case PixelType::Float: return 4;
        case PixelType::UInt64: case PixelType::Int64: case PixelType::Double: case PixelType::Other: return 8;
    }
    return 8;
}

}  // namespace

DecodedImage read_image_file(const std::filesystem::path& path, const BeforePixels& before_pixels) {
    require_regular_input(path);  // a FIFO would block the decoder, a device stream into it
    const std::string format = image_format_of(path);
    // Sizes a few bytes of header declare, checked before the library trusts them and allocates.
    if (format == "openexr") check_exr_header_sizes(path);
    if (format == "png") check_png_chunk_sizes(path);
    DecodedImage image;
    const std::string problem = image_codec().decode(path, format, before_pixels, image);
    if (!problem.empty()) throw InputError({path.string(), 0, 0}, "", problem);
    return image;
}

std::uint64_t decoding_bytes_per_pixel(const ImageHeader& header) {
    // Twice the pixel as stored: the decoder may hold the whole image in that form (the PNG reader does), and
    // OpenImageIO converts to float from a buffer of the same form (a whole TIFF image of 16 M pixels).
    std::uint64_t stored = 0;
    for (PixelType type : header.channel_file_types) stored += stored_bytes(type);
    return header.channel_names.size() * sizeof(float) + 2 * stored;
}

void charge_image_module(MemoryBudget& memory, const std::filesystem::path& file) {
    if (!image_codec_loaded())
        memory.charge(kImageModuleResidentBytes, "the image module that reads it (OpenImageIO's libraries)",
                      {file.string(), 0, 0});
}

}  // namespace isotrace
