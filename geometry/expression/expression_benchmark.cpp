// ns per evaluation of an expression tape in each of its four number types, single-threaded, at random points
// (and boxes of side 0.1). Run: build/bin/expression_benchmark
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "geometry/expression/expression_field.h"

namespace isotrace {
namespace {

const char* const kExpressions[] = {
    "length(p) - 1",
    "sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)",
    "smin(length(p) - 0.6, length(max(abs(p - vec(0.7, 0, 0)) - 0.3, 0)) - 0.05, 0.2)",
    "length(p) - 1 + 0.15 * fbm(2 * p, 6)",
};

const std::vector<Vec3d>& points() {
    static const std::vector<Vec3d> random_points = [] {
        std::mt19937 random(1);
        std::uniform_real_distribution<double> uniform(-2, 2);
        std::vector<Vec3d> result(4096);
        for (Vec3d& p : result) p = {uniform(random), uniform(random), uniform(random)};
        return result;
    }();
    return random_points;
}

template <class Evaluate>
void run(benchmark::State& state, Evaluate evaluate) {
    const auto field = compile_expression({kExpressions[state.range(0)], {}, ""}, {});
    state.SetLabel(std::string(kExpressions[state.range(0)]) + " (" + std::to_string(field->tape_length()) + ")");
    const std::vector<Vec3d>& p = points();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(evaluate(*field, p[i]));
        i = (i + 1) % p.size();
    }
}

IntervalBox box_at(const Vec3d& p) { return {{p.x, p.x + 0.1}, {p.y, p.y + 0.1}, {p.z, p.z + 0.1}}; }

void BM_Value(benchmark::State& s) { run(s, [](const ExpressionField& f, const Vec3d& p) { return f.value(p); }); }
void BM_Gradient(benchmark::State& s) { run(s, [](const ExpressionField& f, const Vec3d& p) { return f.gradient(p); }); }
void BM_ValueRange(benchmark::State& s) {
    run(s, [](const ExpressionField& f, const Vec3d& p) { return f.value_range(box_at(p)); });
}
void BM_SlopeRange(benchmark::State& s) {
    run(s, [](const ExpressionField& f, const Vec3d& p) { return f.slope_range(box_at(p), {0.6, 0.0, 0.8}); });
}

BENCHMARK(BM_Value)->DenseRange(0, 3);
BENCHMARK(BM_Gradient)->DenseRange(0, 3);
BENCHMARK(BM_ValueRange)->DenseRange(0, 3);
BENCHMARK(BM_SlopeRange)->DenseRange(0, 3);

}  // namespace
}  // namespace isotrace

BENCHMARK_MAIN();
