// ns per call of each pattern, single-threaded, at random points. Run: build/bin/patterns_benchmark
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "renderer/textures/patterns/cellular_noise.h"
#include "renderer/textures/patterns/checker.h"
#include "renderer/textures/patterns/fractal_noise.h"
#include "renderer/textures/patterns/gradient_noise.h"
#include "renderer/textures/patterns/grid.h"
#include "renderer/textures/patterns/ramp.h"
#include "renderer/textures/patterns/simplex_noise.h"

namespace isotrace {
namespace {

const std::vector<Vec3f>& points() {
    static const std::vector<Vec3f> random_points = [] {
        std::mt19937 random(1);
        std::uniform_real_distribution<float> uniform(-50, 50);
        std::vector<Vec3f> result(4096);
        for (Vec3f& p : result) p = {uniform(random), uniform(random), uniform(random)};
        return result;
    }();
    return random_points;
}

template <class Pattern>
void run(benchmark::State& state, Pattern pattern) {
    const std::vector<Vec3f>& p = points();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(pattern(p[i]));
        i = (i + 1) % p.size();
    }
}

void BM_GradientNoise(benchmark::State& s) { run(s, [](const Vec3f& p) { return gradient_noise(p, 1); }); }
void BM_SimplexNoise(benchmark::State& s) { run(s, [](const Vec3f& p) { return simplex_noise(p, 1); }); }
const FractalOctaves kGradient5{FractalSettings{}}, kSimplex5{FractalSettings{NoiseBasis::Simplex}};
void BM_FbmGradient5(benchmark::State& s) { run(s, [](const Vec3f& p) { return fbm(p, kGradient5, 0); }); }
void BM_FbmSimplex5(benchmark::State& s) { run(s, [](const Vec3f& p) { return fbm(p, kSimplex5, 0); }); }
void BM_Turbulence5(benchmark::State& s) { run(s, [](const Vec3f& p) { return turbulence(p, kGradient5, 0); }); }
void BM_Ridged5(benchmark::State& s) { run(s, [](const Vec3f& p) { return ridged(p, kGradient5, 0); }); }
void BM_Fbm5Footprint(benchmark::State& s) { run(s, [](const Vec3f& p) { return fbm(p, kGradient5, 0.1f); }); }
void BM_CellularF1(benchmark::State& s) {
    run(s, [](const Vec3f& p) { return cellular(p, 1, 1, CellularOutput::F1, 0); });
}
void BM_Checker(benchmark::State& s) { run(s, [](const Vec3f& p) { return checker(p, 0); }); }
void BM_CheckerFiltered(benchmark::State& s) { run(s, [](const Vec3f& p) { return checker(p, 0.3f); }); }
void BM_GridFiltered(benchmark::State& s) { run(s, [](const Vec3f& p) { return grid(p, 0.1f, 0.3f); }); }
void BM_RampRadial(benchmark::State& s) { run(s, [](const Vec3f& p) { return ramp(p, RampShape::Radial); }); }

BENCHMARK(BM_GradientNoise);
BENCHMARK(BM_SimplexNoise);
BENCHMARK(BM_FbmGradient5);
BENCHMARK(BM_FbmSimplex5);
BENCHMARK(BM_Turbulence5);
BENCHMARK(BM_Ridged5);
BENCHMARK(BM_Fbm5Footprint);
BENCHMARK(BM_CellularF1);
BENCHMARK(BM_Checker);
BENCHMARK(BM_CheckerFiltered);
BENCHMARK(BM_GridFiltered);
BENCHMARK(BM_RampRadial);

}  // namespace
}  // namespace isotrace

BENCHMARK_MAIN();
