// Time per patch of evaluation (F with its derivatives, a 64² or 256² grid of domain points) and of tessellation
// at 64 and 256 segments per side, for 3-, 4-, 5- and 8-sided curved patches. Not run by ctest.
// Run: cmake --build build --target abm_patch_benchmark && build/bin/abm_patch_benchmark
#include <benchmark/benchmark.h>

#include "geometry/abm_patch/abm_patch_test_support.h"
#include "geometry/abm_patch/patch_tessellation.h"

namespace isotrace {
namespace {

AbmPatch patch_of(int sides) {
    return AbmPatch(sides == 3 ? right_triangle_domain() : sides == 4 ? unit_square_domain() : regular_polygon_domain(sides),
                    abm_test::curved_loop(sides));
}

// Arguments: sides, segments per side. One iteration evaluates segments² points spread over the domain.
void Evaluation(benchmark::State& state) {
    const AbmPatch patch = patch_of(int(state.range(0)));
    const int segments = int(state.range(1));
    const DomainPoint c = patch.domain().centre();
    for (auto _ : state) {
        for (int i = 0; i < segments; ++i)
            for (int j = 1; j <= segments; ++j) {
                const DomainPoint edge = patch.domain().on_side(i % patch.domain().sides(), double(i) / segments);
                const double r = double(j) / (segments + 1);
                benchmark::DoNotOptimize(patch.jet({c.x + r * (edge.x - c.x), c.y + r * (edge.y - c.y)}));
            }
    }
    state.SetItemsProcessed(state.iterations() * segments * segments);
}

// Arguments: sides, segments per side (uniform: that many per curve and radially). One iteration = one patch.
void Tessellation(benchmark::State& state) {
    const std::vector<AbmPatch> patches{patch_of(int(state.range(0)))};
    for (auto _ : state) benchmark::DoNotOptimize(tessellate_patches(patches, {.segments = int(state.range(1))}));
}

BENCHMARK(Evaluation)->ArgsProduct({{3, 4, 5, 8}, {64, 256}})->Unit(benchmark::kMillisecond);
BENCHMARK(Tessellation)->ArgsProduct({{3, 4, 5, 8}, {64, 256}})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace isotrace

BENCHMARK_MAIN();
