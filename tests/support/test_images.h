#pragma once
// Test helper: small RGB image files (textures, environment maps) written through the image module.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace isotrace::testing {

// Writes interleaved RGB pixels (row 0 at the top) in the format of `path`'s extension, with the format's default
// compression and no metadata; float pixels are stored as float, 8-bit as 8-bit. Returns `path`.
std::filesystem::path write_rgb_image(const std::filesystem::path& path, int width, int height,
                                      const std::vector<float>& pixels);
std::filesystem::path write_rgb_image(const std::filesystem::path& path, int width, int height,
                                      const std::vector<std::uint8_t>& pixels);

}  // namespace isotrace::testing
