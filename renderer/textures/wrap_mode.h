#pragma once
// What an image lookup reads beyond the image's edges.
#include <cstdint>

namespace isotrace {

enum class WrapMode {
    Repeat,  // tiles the plane
    Clamp,   // the edge texels extend outwards
    Mirror,  // tiles with every other copy reflected, so that edges meet seamlessly
};

// Texel index `i` of a row or column of `size` texels, brought inside [0, size).
inline int wrap_index(int i, int size, WrapMode mode) {
    switch (mode) {
        case WrapMode::Clamp:
            return i < 0 ? 0 : (i >= size ? size - 1 : i);
        case WrapMode::Mirror: {
            const std::int64_t period = 2 * std::int64_t(size);
            std::int64_t k = std::int64_t(i) % period;
            if (k < 0) k += period;
            return int(k < size ? k : period - 1 - k);
        }
        case WrapMode::Repeat:
        default: {
            int k = i % size;
            return k < 0 ? k + size : k;
        }
    }
}

}  // namespace isotrace
