#include "tests/support/test_images.h"

#include <stdexcept>

#include "renderer/image/image_writer.h"

namespace isotrace::testing {
namespace {

std::filesystem::path write_rgb(const std::filesystem::path& path, int width, int height, std::size_t values,
                                const void* pixels, PixelType type) {
    if (values != std::size_t(width) * std::size_t(height) * 3)
        throw std::logic_error("write_rgb_image: pixel count does not match the size");
    ImageEncoding encoding;
    encoding.width = width;
    encoding.height = height;
    encoding.channel_names = {"R", "G", "B"};
    encoding.pixels = pixels;
    encoding.memory_type = encoding.file_type = type;
    write_image_file(path, encoding);
    return path;
}

}  // namespace

std::filesystem::path write_rgb_image(const std::filesystem::path& path, int width, int height,
                                      const std::vector<float>& pixels) {
    return write_rgb(path, width, height, pixels.size(), pixels.data(), PixelType::Float);
}

std::filesystem::path write_rgb_image(const std::filesystem::path& path, int width, int height,
                                      const std::vector<std::uint8_t>& pixels) {
    return write_rgb(path, width, height, pixels.size(), pixels.data(), PixelType::UInt8);
}

}  // namespace isotrace::testing
