#pragma once
// Shared by the pattern tests: reproducible random points and the statistics the tests state bounds on.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <random>
#include <vector>

#include "renderer/math/vec3.h"

namespace isotrace {

// Points uniform in the cube [-extent, extent]³.
inline std::vector<Vec3f> random_points(std::size_t count, float extent, unsigned seed = 1) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> uniform(-extent, extent);
    std::vector<Vec3f> points(count);
    for (Vec3f& p : points) p = {uniform(random), uniform(random), uniform(random)};
    return points;
}

struct Moments {
    double mean = 0, standard_deviation = 0, minimum = INFINITY, maximum = -INFINITY;
};

inline Moments moments(const std::vector<Vec3f>& points, const std::function<float(const Vec3f&)>& field) {
    Moments m;
    double sum = 0, sum_squares = 0;
    for (const Vec3f& p : points) {
        const double v = field(p);
        sum += v;
        sum_squares += v * v;
        m.minimum = std::min(m.minimum, v);
        m.maximum = std::max(m.maximum, v);
    }
    const auto n = static_cast<double>(points.size());
    m.mean = sum / n;
    m.standard_deviation = std::sqrt(std::max(0.0, sum_squares / n - m.mean * m.mean));
    return m;
}

// Pearson's correlation of two fields over the points.
inline double correlation(const std::vector<Vec3f>& points, const std::function<float(const Vec3f&)>& a,
                          const std::function<float(const Vec3f&)>& b) {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    for (const Vec3f& p : points) {
        const double x = a(p), y = b(p);
        sa += x;
        sb += y;
        saa += x * x;
        sbb += y * y;
        sab += x * y;
    }
    const auto n = static_cast<double>(points.size());
    const double covariance = sab / n - sa / n * (sb / n);
    return covariance / std::sqrt((saa / n - sa / n * (sa / n)) * (sbb / n - sb / n * (sb / n)));
}

// The largest change of f(footprint) between footprints `step` apart in [0, end]: small for a smooth fade, the
// size of the jump for a cut.
inline float largest_footprint_step(const std::function<float(float)>& f, float end, float step = 1e-4f) {
    float previous = f(0), largest = 0;
    for (float footprint = step; footprint < end; footprint += step) {
        const float value = f(footprint);
        largest = std::max(largest, std::abs(value - previous));
        previous = value;
    }
    return largest;
}

// The mean of a point-sampled pattern over the square (2-D) or cube (3-D) of side `width` centred on p, by the
// midpoint rule on `steps` samples a side: the reference for the analytic box filters. Returns {2-D, 3-D}.
inline std::array<double, 2> brute_force_box_means(const std::function<float(std::array<float, 2>)>& pattern_2d,
                                                   const std::function<float(const Vec3f&)>& pattern_3d,
                                                   const Vec3f& p, float width, int steps = 60) {
    const auto at = [&](float centre, int i) { return centre + width * ((static_cast<float>(i) + 0.5f) / steps - 0.5f); };
    double sum_2d = 0, sum_3d = 0;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            sum_2d += pattern_2d({at(p.x, i), at(p.y, j)});
            for (int k = 0; k < steps; ++k) sum_3d += pattern_3d({at(p.x, i), at(p.y, j), at(p.z, k)});
        }
    return {sum_2d / (steps * steps), sum_3d / (static_cast<double>(steps) * steps * steps)};
}

}  // namespace isotrace
