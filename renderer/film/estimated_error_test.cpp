// The reference-mode error estimate, worked by hand on tiny films.
#include "renderer/film/estimated_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace isotrace {
namespace {

Film film(int width, int height) {
    FilmSettings s;
    s.raster = {width, height};
    s.crop = {0, 0, width, height};
    return Film(s);
}

void add(Film& f, int x, int y, float value) {
    CameraSample sample;
    sample.radiance = Rgb(value);
    f.add_sample(x, y, sample);
}

TEST(EstimatedRelativeError, WorkedByHand) {
    // Pixel 0: samples 1 and 3: mean 2, per-sample variance 2 (unbiased), variance of the mean 1;
    // relative: 1 / 2.01^2. Pixel 1: samples 0.5 and 0.5: variance 0. E = sqrt((1 / 2.01^2 + 0) / 2).
    Film f = film(2, 1);
    add(f, 0, 0, 1);
    add(f, 0, 0, 3);
    add(f, 1, 0, 0.5f);
    add(f, 1, 0, 0.5f);
    EXPECT_NEAR(estimated_relative_error(f), std::sqrt(0.5 / (2.01 * 2.01)), 1e-12);
    const PixelStatistics p = f.pixel_statistics(0, 0);
    EXPECT_DOUBLE_EQ(p.mean[1], 2.0);
    EXPECT_DOUBLE_EQ(p.variance_of_mean[1], 1.0);
    EXPECT_EQ(p.samples, 2u);
}

TEST(EstimatedRelativeError, FallsAsOneOverRootSampleCount) {
    // Alternating samples 0 and 2 (mean 1, per-sample variance n / (n - 1)): Var[mean] = 1 / (n - 1).
    for (int n : {4, 64, 1024}) {
        Film f = film(1, 1);
        for (int i = 0; i < n; ++i) add(f, 0, 0, i % 2 ? 2.0f : 0.0f);
        EXPECT_NEAR(estimated_relative_error(f), std::sqrt(1.0 / (n - 1)) / 1.01, 1e-12) << n;
    }
}

TEST(EstimatedRelativeError, InfiniteBelowTwoSamples) {
    Film f = film(2, 1);
    add(f, 0, 0, 1);
    add(f, 0, 0, 1);
    add(f, 1, 0, 1);
    EXPECT_TRUE(std::isinf(estimated_relative_error(f)));
}

}  // namespace
}  // namespace isotrace
