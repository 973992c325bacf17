#include "renderer/image_compare/separable_filter.h"

#include <tbb/blocked_range.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "renderer/core/parallel_for.h"

namespace isotrace {
namespace {

// One pass along rows (step 1) or columns (step width) of every line.
std::vector<float> filter_lines(const std::vector<float>& plane, int width, int height, const Kernel1d& kernel,
                                bool along_rows) {
    if (kernel.size() % 2 != 1) throw std::invalid_argument("filter kernels must have odd length");
    const int radius = int(kernel.size() / 2);
    const int length = along_rows ? width : height;   // samples on one line
    const int lines = along_rows ? height : width;
    const std::size_t step = along_rows ? 1 : std::size_t(width);
    const std::size_t line_step = along_rows ? std::size_t(width) : 1;
    std::vector<float> out(plane.size());
    parallel_for(tbb::blocked_range<int>(0, lines), [&](const tbb::blocked_range<int>& range) {
        for (int line = range.begin(); line != range.end(); ++line) {
            const float* in = plane.data() + std::size_t(line) * line_step;
            float* result = out.data() + std::size_t(line) * line_step;
            for (int i = 0; i < length; ++i) {
                double sum = 0;
                for (int k = -radius; k <= radius; ++k) {
                    const int j = std::clamp(i + k, 0, length - 1);
                    sum += kernel[std::size_t(k + radius)] * double(in[std::size_t(j) * step]);
                }
                result[std::size_t(i) * step] = float(sum);
            }
        }
    });
    return out;
}

}  // namespace

std::vector<float> filter_separable(const std::vector<float>& plane, int width, int height, const Kernel1d& along_x,
                                    const Kernel1d& along_y) {
    if (plane.size() != std::size_t(width) * std::size_t(height))
        throw std::invalid_argument("filter_separable: plane size does not match width x height");
    return filter_lines(filter_lines(plane, width, height, along_x, true), width, height, along_y, false);
}

Kernel1d normalised_gaussian(double sigma, int radius) {
    Kernel1d kernel(std::size_t(2 * radius + 1));
    double sum = 0;
    for (int k = -radius; k <= radius; ++k) sum += kernel[std::size_t(k + radius)] = std::exp(-k * k / (2 * sigma * sigma));
    for (double& w : kernel) w /= sum;
    return kernel;
}

}  // namespace isotrace
