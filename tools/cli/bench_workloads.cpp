#include "tools/cli/bench_workloads.h"

#include <filesystem>

#include "geometry/polygonize/polygonize_field.h"
#include "renderer/core/input_error.h"
#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"
#include "tools/cli/object_field.h"
#include "tools/cli/peak_memory.h"
#include "tools/cli/secondary_ray_lists.h"

namespace isotrace::cli {
namespace {

const char* unit_of(WorkloadKind kind) {
    switch (kind) {
        case WorkloadKind::PathTracer: return "Msamples/s";
        case WorkloadKind::MarchingCubes:
        case WorkloadKind::DualContouring:
        case WorkloadKind::SphericalDualContouring: return "Mtriangles/s";
        default: return "Mrays/s";
    }
}

// The object the polygoniser workloads mesh: the dog of metacube_dog (a blended metacube group), the cloud of
// blobs_10k (10 000 metaballs).
std::string meshed_object(const std::string& scene_path) {
    return std::filesystem::path(scene_path).stem() == "blobs_10k" ? "cloud" : "dog";
}

std::optional<PolygonizeMethod> method_of(WorkloadKind kind) {
    switch (kind) {
        case WorkloadKind::MarchingCubes: return PolygonizeMethod::MarchingCubes;
        case WorkloadKind::DualContouring: return PolygonizeMethod::DualContouring;
        case WorkloadKind::SphericalDualContouring: return PolygonizeMethod::SphericalDualContouring;
        default: return std::nullopt;
    }
}

// The scene's workloads and the per-scene timing state they share: secondary rays are built once.
class SceneWorkloads {
public:
    SceneWorkloads(const std::string& path, const SuiteSettings& settings) : settings_(settings) {
        if (!std::filesystem::is_regular_file(path))
            throw InputError({}, "scene",
                             "\"" + path + "\" does not exist (isotrace bench runs from the source tree)");
        SceneOverrides overrides;
        if (settings.resolution) overrides.settings.push_back(resolution_setting(*settings.resolution));
        overrides.settings.push_back(spp_setting(settings.path_spp));
        scene_ = load_scene(path, overrides);
    }

    void run(WorkloadKind kind, WorkloadResult& result) {
        const BuildStatistics& build = scene_->scene->build_statistics();
        result.build_seconds = build.seconds;
        result.scene_bytes = std::uint64_t(std::max<std::int64_t>(build.embree_bytes, 0)) + build.shape_bytes;
        for (int threads : settings_.threads) {
            RayCastTiming timing = time(kind, threads);
            drop_warm_up(timing);
            result.timings.push_back(std::move(timing));
        }
        result.work_per_run = double(result.timings.front().rays());
    }

private:
    RayCastTiming time(WorkloadKind kind, int threads) {
        const int runs = kWarmUpRuns + settings_.repeats;
        const double min_seconds = settings_.min_run_seconds;
        const std::vector<const LoadedScene*> scenes = {scene_.get()};
        switch (kind) {
            case WorkloadKind::PrimaryRays: return time_primary_rays(scenes, threads, runs, min_seconds).front();
            case WorkloadKind::ShadowRays:
                return time_secondary_rays(scenes, secondary().shadow, SecondaryQuery::Occlusion, threads, runs,
                                           min_seconds)
                    .front();
            case WorkloadKind::BounceRays:
                return time_secondary_rays(scenes, secondary().bounce, SecondaryQuery::NearestHit, threads, runs,
                                           min_seconds)
                    .front();
            case WorkloadKind::PathTracer:
                return time_taking_turns(1, threads, runs, [&](RayCastTiming& timing, std::size_t) {
                    RenderOptions options;
                    options.spp = settings_.path_spp;
                    const RenderResult render = render_scene(*scene_, options);
                    timing.ray_count = std::size_t(scene_->film.crop.width()) * std::size_t(scene_->film.crop.height()) *
                                       std::size_t(render.completed_spp);
                }, min_seconds).front();
            case WorkloadKind::MarchingCubes:
            case WorkloadKind::DualContouring:
            case WorkloadKind::SphericalDualContouring: {
                const std::unique_ptr<ImplicitField> field =
                    field_of(find_object(*scene_->scene, meshed_object(scene_->path), scene_->path));
                PolygonizeOptions options;
                options.method = *method_of(kind);
                options.depth = settings_.mesh_depth;
                return time_taking_turns(1, threads, runs, [&](RayCastTiming& timing, std::size_t) {
                    timing.ray_count = polygonize_field(*field, options).mesh.triangles.size();
                }, min_seconds).front();
            }
            case WorkloadKind::BlobComparison: break;
        }
        throw std::logic_error("the blob comparison is not a suite workload");
    }

    const SecondaryRayLists& secondary() {
        if (!secondary_) secondary_ = build_secondary_rays(*scene_);
        return *secondary_;
    }

    const SuiteSettings& settings_;
    std::unique_ptr<LoadedScene> scene_;
    std::optional<SecondaryRayLists> secondary_;
};

}  // namespace

const char* kind_name(WorkloadKind kind) {
    switch (kind) {
        case WorkloadKind::PrimaryRays: return "primary";
        case WorkloadKind::ShadowRays: return "shadow";
        case WorkloadKind::BounceRays: return "bounce";
        case WorkloadKind::PathTracer: return "path";
        case WorkloadKind::MarchingCubes: return "mesh_mc";
        case WorkloadKind::DualContouring: return "mesh_dc";
        case WorkloadKind::SphericalDualContouring: return "mesh_sdc";
        case WorkloadKind::BlobComparison: return "direct_vs_tessellated";
    }
    return "?";
}

std::vector<Workload> suite_workloads() {
    using K = WorkloadKind;
    const std::vector<K> rays = {K::PrimaryRays, K::ShadowRays, K::BounceRays};
    const std::vector<K> rays_and_paths = {K::PrimaryRays, K::ShadowRays, K::BounceRays, K::PathTracer};
    // Triangles (the Cornell box; Embree's tutorial box lit by a point, as tools/compare-embree renders it; the
    // sweep-deformed bunny, traced as its mesh), blob groups of growing size (their scenes use the AOV integrator,
    // so no path tracer workload; blobs_10k is meshed by the polygonisers), metacubes (and the polygonisers; the same dog again with textured, bumped and
    // blended principled materials, for the cost of shading), superquadrics, CSG and multi-sided patches.
    const std::vector<std::pair<std::string, std::vector<K>>> scenes = {
        {"cornell_box", rays_and_paths},
        {"embree_cornell_box", {K::PathTracer}},
        {"sweep_bunny", rays_and_paths},
        {"blobs_1k", rays},
        {"blobs_10k", {K::PrimaryRays, K::ShadowRays, K::BounceRays, K::MarchingCubes, K::DualContouring,
                       K::SphericalDualContouring}},
        {"blobs_100k", rays},
        {"metacube_dog", {K::PrimaryRays, K::ShadowRays, K::BounceRays, K::PathTracer, K::MarchingCubes,
                          K::DualContouring, K::SphericalDualContouring}},
        {"spotted_dog", {K::PathTracer}},
        {"superquadric_gallery", rays_and_paths},
        {"csg_cup", rays_and_paths},
        {"abm_patches", rays_and_paths}};
    std::vector<Workload> workloads;
    for (const auto& [scene, kinds] : scenes)
        for (K kind : kinds) workloads.push_back({scene + "/" + kind_name(kind), "scenes/" + scene + ".json", kind});
    workloads.push_back({std::string("blobs/") + kind_name(K::BlobComparison), "", K::BlobComparison});
    return workloads;
}

std::vector<Workload> workloads_matching(const std::vector<Workload>& workloads, const std::regex& filter) {
    std::vector<Workload> selected;
    for (const Workload& w : workloads)
        if (std::regex_search(w.name, filter)) selected.push_back(w);
    return selected;
}

std::vector<double> WorkloadResult::throughputs(const RayCastTiming& timing) const {
    std::vector<double> values;
    for (double seconds : timing.seconds) values.push_back(seconds > 0 ? work_per_run / seconds * 1e-6 : 0);
    return values;
}

std::vector<WorkloadResult> run_workloads(const std::vector<Workload>& workloads, const SuiteSettings& settings,
                                          const std::function<void(const std::string&)>& log) {
    std::vector<WorkloadResult> results;
    std::unique_ptr<SceneWorkloads> scene;
    std::string loaded;
    for (const Workload& workload : workloads) {
        if (workload.kind == WorkloadKind::BlobComparison) continue;
        reset_peak_memory();  // before loading the scene for its first workload, before the runs for the others
        if (workload.scene != loaded) {
            scene.reset();  // free the previous scene first
            log(workload.scene + ": loading");
            scene = std::make_unique<SceneWorkloads>(workload.scene, settings);
            loaded = workload.scene;
        }
        log(workload.name + ": warm-up and " + std::to_string(settings.repeats) + " run(s) per thread count");
        WorkloadResult result;
        result.workload = workload;
        result.unit = unit_of(workload.kind);
        scene->run(workload.kind, result);
        result.peak_memory_bytes = peak_memory_bytes();
        results.push_back(std::move(result));
    }
    return results;
}

}  // namespace isotrace::cli
