#pragma once
// MipPyramid: an image and its box-filtered reductions (each level half the size of the one before, down to 1x1),
// looked up with trilinear filtering: bilinear within the two levels whose texels are nearest the footprint's
// size, blended between them. A footprint of at most one texel reads the full-resolution level alone, bilinearly.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "renderer/textures/wrap_mode.h"

namespace isotrace {

class MipPyramid {
public:
    // `level0`: width x height texels of `channels` interleaved floats, row 0 at the top of the image.
    // `reduced_levels` false keeps level 0 alone (texel access only).
    MipPyramid(int width, int height, int channels, std::vector<float> level0, bool reduced_levels);
    // Moving keeps the levels' texels where they are; a copy would point into the original's.
    MipPyramid(MipPyramid&&) = default;
    MipPyramid& operator=(MipPyramid&&) = default;
    MipPyramid(const MipPyramid&) = delete;
    MipPyramid& operator=(const MipPyramid&) = delete;

    // Texels of every level after the first, for charging them to a memory budget before they are built.
    static std::uint64_t reduced_texel_count(int width, int height);

    int channels() const { return channels_; }
    int level_count() const { return int(levels_.size()); }
    int width(int level = 0) const { return levels_[std::size_t(level)].width; }
    int height(int level = 0) const { return levels_[std::size_t(level)].height; }
    // The first of `channels` floats of texel (x, y) of `level`, x and y inside the level.
    const float* texel(int level, int x, int y) const {
        const Level& l = levels_[std::size_t(level)];
        return l.texels + (std::size_t(y) * std::size_t(l.width) + std::size_t(x)) * std::size_t(channels_);
    }

    // The first C channels at uv ((0, 0) the bottom-left corner of the image, (1, 1) the top right) for a
    // footprint `texels` wide in level-0 texels.
    template <int C>
    std::array<float, C> lookup(std::array<float, 2> uv, float texels, WrapMode wrap) const {
        if (!(texels > 1) || level_count() == 1) return bilinear<C>(0, uv, wrap);
        const float level = std::min(std::log2(texels), float(level_count() - 1));
        const int fine = int(level);
        if (fine >= level_count() - 1) return bilinear<C>(fine, uv, wrap);
        const float t = level - float(fine);
        std::array<float, C> a = bilinear<C>(fine, uv, wrap);
        const std::array<float, C> b = bilinear<C>(fine + 1, uv, wrap);
        for (int c = 0; c < C; ++c) a[c] = a[c] * (1 - t) + b[c] * t;
        return a;
    }

    template <int C>
    std::array<float, C> bilinear(int level, std::array<float, 2> uv, WrapMode wrap) const {
        const Level& l = levels_[std::size_t(level)];
        // Texel centres sit at half-integer coordinates; v runs up the image.
        const float x = texel_coordinate(uv[0] * float(l.width) - 0.5f);
        const float y = texel_coordinate((1.0f - uv[1]) * float(l.height) - 0.5f);
        const float fx = std::floor(x), fy = std::floor(y);
        const float tx = x - fx, ty = y - fy;
        const int x0 = wrap_index(int(fx), l.width, wrap), x1 = wrap_index(int(fx) + 1, l.width, wrap);
        const int y0 = wrap_index(int(fy), l.height, wrap), y1 = wrap_index(int(fy) + 1, l.height, wrap);
        const float w00 = (1 - tx) * (1 - ty), w10 = tx * (1 - ty), w01 = (1 - tx) * ty, w11 = tx * ty;
        const float* t00 = texel(level, x0, y0);
        const float* t10 = texel(level, x1, y0);
        const float* t01 = texel(level, x0, y1);
        const float* t11 = texel(level, x1, y1);
        std::array<float, C> result;
        for (int c = 0; c < C; ++c) result[c] = t00[c] * w00 + t10[c] * w10 + t01[c] * w01 + t11[c] * w11;
        return result;
    }

private:
    struct Level {
        int width, height;
        const float* texels;
    };

    // Coordinates too large for an int (or NaN, from a degenerate mapping) read texel 0: floats that large are
    // whole numbers anyway.
    static float texel_coordinate(float x) { return std::abs(x) < 0x1p30f ? x : 0.0f; }

    int channels_;
    std::vector<float> level0_;
    std::vector<float> reduced_;  // every level after the first, one after another
    std::vector<Level> levels_;
};

}  // namespace isotrace
