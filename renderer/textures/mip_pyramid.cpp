#include "renderer/textures/mip_pyramid.h"

#include <algorithm>

#include "renderer/core/memory_budget.h"

namespace isotrace {
namespace {

int reduced(int size) { return std::max(1, size / 2); }

// Texel x of a level `to` wide covers texels [begin, end) of the level `from` wide before it: two, or three
// where `from` is odd, so that every texel is counted.
std::array<int, 2> box(int x, int from, int to) {
    return {int(std::int64_t(x) * from / to), int(std::int64_t(x + 1) * from / to)};
}

}  // namespace

std::uint64_t MipPyramid::reduced_texel_count(int width, int height) {
    std::uint64_t total = 0;
    // At most 31 halvings of an int size.
    while (width > 1 || height > 1) {
        width = reduced(width);
        height = reduced(height);
        total = saturating_sum({total, saturating_product({std::uint64_t(width), std::uint64_t(height)})});
    }
    return total;
}

MipPyramid::MipPyramid(int width, int height, int channels, std::vector<float> level0, bool reduced_levels)
    : channels_(channels), level0_(std::move(level0)) {
    levels_.push_back({width, height, level0_.data()});
    if (!reduced_levels) return;
    reduced_.resize(std::size_t(reduced_texel_count(width, height)) * std::size_t(channels));
    float* next = reduced_.data();
    while (width > 1 || height > 1) {
        const Level from = levels_.back();
        const int w = reduced(width), h = reduced(height);
        for (int y = 0; y < h; ++y) {
            const auto [y_begin, y_end] = box(y, from.height, h);
            for (int x = 0; x < w; ++x) {
                const auto [x_begin, x_end] = box(x, from.width, w);
                float* out = next + (std::size_t(y) * std::size_t(w) + std::size_t(x)) * std::size_t(channels);
                std::fill(out, out + channels, 0.0f);
                for (int sy = y_begin; sy < y_end; ++sy)
                    for (int sx = x_begin; sx < x_end; ++sx) {
                        const float* in = from.texels + (std::size_t(sy) * std::size_t(from.width) + std::size_t(sx)) *
                                                            std::size_t(channels);
                        for (int c = 0; c < channels; ++c) out[c] += in[c];
                    }
                const float weight = 1.0f / float((y_end - y_begin) * (x_end - x_begin));
                for (int c = 0; c < channels; ++c) out[c] *= weight;
            }
        }
        levels_.push_back({w, h, next});
        next += std::size_t(w) * std::size_t(h) * std::size_t(channels);
        width = w;
        height = h;
    }
}

}  // namespace isotrace
