#pragma once
// The fixed workloads of isotrace bench: for shipped scenes, primary, shadow and one-bounce diffuse rays
// and the full path tracer, and the three polygonisers on metacube_dog and blobs_10k. Each workload is named "<scene>/<kind>" (the
// names --filter matches); each runs once as a warm-up and then `repeats` timed times per thread count.
// The blob direct-vs-tessellated comparison is a workload of the registry too ("blobs/direct_vs_tessellated")
// but is run by tools/cli/blob_benchmark.h, which measures its own way.
#include <cstdint>
#include <functional>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "renderer/plugin/camera.h"
#include "tools/cli/ray_cast_timing.h"

namespace isotrace::cli {

enum class WorkloadKind {
    PrimaryRays,
    ShadowRays,
    BounceRays,
    PathTracer,
    MarchingCubes,
    DualContouring,
    SphericalDualContouring,
    BlobComparison
};

// "primary", "shadow", "bounce", "path", "mesh_mc", "mesh_dc", "mesh_sdc", "direct_vs_tessellated": the part of a
// name after the scene.
const char* kind_name(WorkloadKind kind);

struct Workload {
    std::string name;   // "cornell_box/primary"
    std::string scene;  // path relative to the source tree: "scenes/cornell_box.json"
    WorkloadKind kind;
};

// The whole suite in order, workloads of one scene next to each other.
std::vector<Workload> suite_workloads();

// The workloads whose names std::regex_search finds `filter` in.
std::vector<Workload> workloads_matching(const std::vector<Workload>& workloads, const std::regex& filter);

struct SuiteSettings {
    std::vector<int> threads = {1};
    int repeats = 3;
    std::optional<RasterSize> resolution;  // of the ray and path workloads; default: each scene's own
    int path_spp = 4;                      // samples per pixel of one path tracer run
    int mesh_depth = 8;                    // octree depth of the polygoniser workloads
    double min_run_seconds = 0;            // a timed run repeats its work until it lasts this long (time_taking_turns)
};

struct WorkloadResult {
    Workload workload;
    std::string unit;                       // "Mrays/s", "Msamples/s" or "Mtriangles/s"
    double work_per_run = 0;                // rays, samples or triangles per run
    double build_seconds = 0;               // the scene's Embree build
    std::uint64_t scene_bytes = 0;          // Embree's and the shapes' memory
    std::uint64_t peak_memory_bytes = 0;    // peak resident memory from loading the scene to the last run
    std::vector<RayCastTiming> timings;     // one per thread count (warm-up runs left out)

    std::vector<double> throughputs(const RayCastTiming& timing) const;  // work_per_run / seconds, in `unit`
};

// Runs the workloads (except BlobComparison, which it skips), loading each scene once for all its workloads.
// `log` receives one line per step. Throws InputError when a scene is missing.
std::vector<WorkloadResult> run_workloads(const std::vector<Workload>& workloads, const SuiteSettings& settings,
                                          const std::function<void(const std::string&)>& log);

}  // namespace isotrace::cli
