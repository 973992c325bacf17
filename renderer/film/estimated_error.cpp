#include "renderer/film/estimated_error.h"

#include <cmath>

#include "renderer/image_compare/pixel_error.h"

namespace isotrace {

double estimated_relative_error(const Film& film) {
    const PixelBounds& area = film.bounds();
    if (area.area() == 0) return 0;
    double sum = 0;
    for (int y = area.y0; y < area.y1; ++y) {
        for (int x = area.x0; x < area.x1; ++x) {
            const PixelStatistics pixel = film.pixel_statistics(x, y);
            for (int c = 0; c < 3; ++c) {
                const double scale = std::abs(pixel.mean[c]) + kRelativeMseEpsilon;
                sum += pixel.variance_of_mean[c] / (scale * scale);
            }
        }
    }
    return std::sqrt(sum / (3.0 * double(area.area())));
}

}  // namespace isotrace
