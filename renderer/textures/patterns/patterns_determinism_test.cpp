// Every pattern is a function of its arguments: evaluated in parallel it gives the serial results bit for bit.
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <vector>

#include "renderer/core/parallel_for.h"
#include "renderer/textures/patterns/cellular_noise.h"
#include "renderer/textures/patterns/checker.h"
#include "renderer/textures/patterns/fractal_noise.h"
#include "renderer/textures/patterns/gradient_noise.h"
#include "renderer/textures/patterns/grid.h"
#include "renderer/textures/patterns/pattern_test_support.h"
#include "renderer/textures/patterns/ramp.h"
#include "renderer/textures/patterns/simplex_noise.h"

namespace isotrace {
namespace {

TEST(PatternsDeterminism, ParallelEvaluationEqualsSerialBitForBit) {
    const auto points = random_points(20000, 30);
    // Varying seeds and footprints per point, so that threads interleave different arguments.
    const auto seed = [](std::size_t i) { return static_cast<std::uint32_t>(i % 7); };
    const auto footprint = [](std::size_t i) { return static_cast<float>(i % 5) * 0.1f; };
    std::vector<FractalOctaves> gradient_fractals, simplex_fractals;
    for (std::uint32_t s = 0; s < 7; ++s) {
        gradient_fractals.emplace_back(FractalSettings{NoiseBasis::Gradient, 6, 2, 0.5f, s});
        simplex_fractals.emplace_back(FractalSettings{NoiseBasis::Simplex, 6, 2, 0.5f, s});
    }
    const std::vector<std::function<float(const Vec3f&, std::size_t)>> patterns = {
        [&](const Vec3f& p, std::size_t i) { return gradient_noise(p, seed(i)); },
        [&](const Vec3f& p, std::size_t i) { return simplex_noise(p, seed(i)); },
        [&](const Vec3f& p, std::size_t i) { return fbm(p, gradient_fractals[seed(i)], footprint(i)); },
        [&](const Vec3f& p, std::size_t i) { return turbulence(p, simplex_fractals[seed(i)], footprint(i)); },
        [&](const Vec3f& p, std::size_t i) { return ridged(p, gradient_fractals[seed(i)], footprint(i)); },
        [&](const Vec3f& p, std::size_t i) { return cellular(p, seed(i), 1, CellularOutput::F2MinusF1, footprint(i) * 2); },
        [&](const Vec3f& p, std::size_t i) { return cellular(p, seed(i), 0.8f, CellularOutput::CellValue, footprint(i) * 2); },
        [&](const Vec3f& p, std::size_t i) { return checker(p, footprint(i)); },
        [&](const Vec3f& p, std::size_t i) { return grid_2d({p.x, p.z}, 0.1f, footprint(i)); },
        [&](const Vec3f& p, std::size_t) { return ramp(p, RampShape::Radial); },
    };
    for (std::size_t pattern = 0; pattern < patterns.size(); ++pattern) {
        std::vector<float> serial(points.size()), parallel(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) serial[i] = patterns[pattern](points[i], i);
        parallel_for(std::size_t(0), points.size(), [&](std::size_t i) { parallel[i] = patterns[pattern](points[i], i); });
        EXPECT_EQ(std::memcmp(serial.data(), parallel.data(), serial.size() * sizeof(float)), 0) << pattern;
    }
}

}  // namespace
}  // namespace isotrace
