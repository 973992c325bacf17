#pragma once
// The blob-group benchmark of issue 4, in one process and one run: every scene is loaded twice and traced with
// primary rays only, directly (blob groups as Embree user geometry) and with every blob group replaced by its
// tessellation (geometry/polygonize) traced natively by Embree as triangles, taking turns, on each thread count.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tools/cli/ray_cast_timing.h"
#include "tools/cli/tessellation_options.h"

namespace isotrace::cli {

struct BlobBenchmarkSettings {
    std::vector<std::string> scenes;
    std::vector<int> threads;
    int repeats = 3;
    std::optional<RasterSize> resolution;  // default: each scene's own
    TessellationOptions tessellation;
};

// One way of tracing a scene: build cost and ray timings per thread count (the runs of the direct and the
// tessellated scene alternate, so their i-th runs saw the same machine).
struct TracedScene {
    double build_seconds = 0;
    std::int64_t embree_bytes = 0;
    std::size_t shape_bytes = 0;
    std::vector<RayCastTiming> timings;  // in the order of the settings' thread counts
};

struct TessellationSummary {
    double cell_size = 0;
    double seconds = 0;
    std::size_t triangles = 0, vertices = 0;
    bool closed = true;  // every mesh closed and consistently oriented
};

struct SceneBenchmark {
    std::string scene;
    std::size_t elements = 0;
    TracedScene direct, tessellated;
    TessellationSummary tessellation;
    double pixel_agreement = 0;          // fraction of pixels where both hit or both miss
    double median_depth_difference = 0;  // |direct − tessellated| view depth over pixels both hit, world units
};

// Throws InputError when a scene holds no blob group. `log` receives one line per step.
std::vector<SceneBenchmark> run_blob_benchmark(const BlobBenchmarkSettings& settings,
                                               const std::function<void(const std::string&)>& log);

}  // namespace isotrace::cli
