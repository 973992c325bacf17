#pragma once
// An RGB image of floats, the common currency of the image-comparison metrics: three values per pixel, rows
// from the top. Whether the values are scene-linear or display-referred is the caller's business.
#include <cstddef>
#include <vector>

namespace isotrace {

struct RgbImage {
    int width = 0, height = 0;
    std::vector<float> values;  // width * height * 3

    RgbImage() = default;
    RgbImage(int width, int height, float grey = 0) : width(width), height(height),
        values(std::size_t(width) * std::size_t(height) * 3, grey) {}
    std::size_t pixel_count() const { return std::size_t(width) * std::size_t(height); }
    float* pixel(int x, int y) { return values.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3; }
    const float* pixel(int x, int y) const {
        return values.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
    }
};

// Rec. 709 / sRGB-primaries luminance of one pixel.
inline float luminance(const float* rgb) { return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2]; }

// One luminance value per pixel.
std::vector<float> luminance_plane(const RgbImage& image);

// Throws std::invalid_argument unless both images have the same, non-zero size.
void require_same_size(const RgbImage& reference, const RgbImage& test);

}  // namespace isotrace
