#include "tools/cli/benchmark_run.h"

#include <cstring>

#include "geometry/polygonize/polygonize_field.h"
#include "renderer/core/fnv_hash.h"
#include "renderer/core/input_error.h"
#include "renderer/render/tile_renderer.h"
#include "tools/cli/object_field.h"
#include "tools/cli/ray_cast_timing.h"

namespace isotrace::cli {
namespace {

template <typename T>
std::uint64_t hash_of(const std::vector<T>& values, std::uint64_t h) {
    return fnv1a_64(std::string_view(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)), h);
}

}  // namespace

BenchmarkWorkloadRunner::BenchmarkWorkloadRunner(const BenchmarkWorkload& workload,
                                                 const std::filesystem::path& folder)
    : workload_(workload) {
    const std::filesystem::path scene = folder / workload.scene;
    std::error_code ignored;
    if (!std::filesystem::is_regular_file(scene, ignored))
        throw InputError({scene.string(), 0, 0}, "", "the benchmark scene is missing: the suite folder is incomplete");
    scene_ = load_scene(scene.string());
}

BenchmarkWorkloadRunner::~BenchmarkWorkloadRunner() = default;

std::string BenchmarkWorkloadRunner::unit() const {
    switch (workload_.kind) {
        case BenchmarkUnitKind::Render: {
            RenderOptions options;
            options.spp = scene_->spp;
            const RenderResult render = render_scene(*scene_, options);
            return hex64(fnv1a_64(render.film->state()));
        }
        case BenchmarkUnitKind::Polygonise: {
            const std::unique_ptr<ImplicitField> field =
                field_of(find_object(*scene_->scene, workload_.object, scene_->path));
            PolygonizeOptions options;
            options.method = PolygonizeMethod::DualContouring;
            options.depth = workload_.depth;
            const Polygonization mesh = polygonize_field(*field, options);
            return hex64(hash_of(mesh.mesh.triangles, hash_of(mesh.mesh.positions, kFnv1aOffset)));
        }
    }
    return "";
}

BenchmarkRun BenchmarkWorkloadRunner::run(int threads, int warm_up, int units,
                                          const std::function<void()>& on_unit) const {
    BenchmarkRun run;
    run.threads = threads;
    RayCastTiming timing = time_taking_turns(1, threads, warm_up + units, [&](RayCastTiming&, std::size_t) {
        run.hashes.insert(unit());
        on_unit();
    }).front();
    run.seconds.assign(timing.seconds.begin() + warm_up, timing.seconds.end());
    return run;
}

}  // namespace isotrace::cli
