#pragma once
// ImageBuffer: what films resolve to, image files are written from, and comparisons read.
#include <cstddef>
#include <string>
#include <vector>

namespace isotrace {

// Interleaved float image with named channels.
struct ImageBuffer {
    int width = 0, height = 0;
    std::vector<std::string> channels;
    std::vector<float> pixels;  // width * height * channels.size()
    float* pixel(int x, int y) { return pixels.data() + (std::size_t(y) * width + x) * channels.size(); }
};

}  // namespace isotrace
