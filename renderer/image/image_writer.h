#pragma once
// Writes rendered images: scene-linear EXR with every channel and metadata, or a display-referred 8-bit
// PNG/JPEG of the beauty through the OCIO display/view transform.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/image/image_buffer.h"
#include "renderer/image/image_codec.h"
#include "renderer/image/image_metadata.h"
#include "renderer/plugin/camera.h"

namespace isotrace {

class ColourSystem;

// Placement of a (possibly cropped) image inside the full raster.
struct ImageWindow {
    RasterSize full;
    int x = 0, y = 0;  // data window origin
};

enum class ImageKind { Exr, Display };

// Chooses by extension: .exr -> Exr; .png/.jpg/.jpeg/.tif/.tiff -> Display. Throws InputError otherwise.
ImageKind image_kind_for(const std::filesystem::path& path);

// Encodes `image` in the format of `path`'s extension and writes the file atomically (atomic_file.h): on any
// failure the target is untouched. Throws std::runtime_error naming the path.
void write_image_file(const std::filesystem::path& path, const ImageEncoding& image);

void write_exr(const std::filesystem::path& path, const ImageBuffer& image, const ImageWindow& window,
               bool half_float, const ImageMetadata& metadata);

// An 8-bit single-channel image written as is, without colour transform (range images), atomically.
void write_grey8_image(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& pixels,
                       const ImageMetadata& metadata);

// 8-bit RGB already encoded for display (false-colour error maps), written as is, atomically.
void write_rgb8_image(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& pixels,
                      const ImageMetadata& metadata);

void write_display_image(const std::filesystem::path& path, const ImageBuffer& image, const ColourSystem& colours,
                         const std::string& display, const std::string& view, const ImageMetadata& metadata);

}  // namespace isotrace
