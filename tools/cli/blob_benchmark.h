#pragma once
// The implicit-surface benchmark, in one process and one run: every scene is loaded twice and traced with primary,
// shadow and one-bounce diffuse rays, directly (blob groups, isosurfaces, superquadrics and CSG solids as Embree user
// geometry) and with each of them replaced by its tessellation (geometry/polygonize; all but blob groups by dual
// contouring at 2⁷ cells along their field's bounds, or --cell-size) traced natively by Embree as triangles, taking
// turns, on each thread count. The secondary rays are built once from the direct scene's primary hits
// (tools/cli/secondary_ray_lists.h), starting half the coarsest tessellation cell off the surface, and the same lists
// are traced in both scenes.
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
    double min_run_seconds = 0;  // a timed run repeats its rays until it lasts this long (time_taking_turns)
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
    double cell_size = 0;      // the finest of the tessellations' cells, in the world (a cell's longest edge once placed)
    double coarsest_cell = 0;  // and the coarsest
    double seconds = 0;
    std::size_t triangles = 0, vertices = 0;
    bool closed = true;  // every mesh closed and consistently oriented
};

// One kind of secondary ray: the same list traced in both scenes.
struct SecondaryBenchmark {
    std::size_t rays = 0;
    std::vector<RayCastTiming> direct, tessellated;  // in the order of the settings' thread counts
    double agreement = 1;            // fraction of the rays with the same answer (occluded / hit) in both scenes
    double direct_hit_fraction = 0;  // fraction of the rays occluded / hitting something in the direct scene
};

// How far off the exact surface the secondary rays start, in tessellation cells. A mesh strays from the surface by a
// fraction of a cell (dual contouring's vertices lie outside convex parts, chords inside concave ones): a ray
// starting closer would hit the mesh at once where the exact surface lets it go, and agreement would measure that
// band instead of the surfaces. Half a cell takes the shadow and bounce agreement of the gallery's isosurfaces from
// 55-98 % to 99.9 %; a whole cell or two changes it by less than 0.1 %.
constexpr double kSecondaryClearanceInCells = 0.5;

struct SceneBenchmark {
    std::string scene;
    std::size_t elements = 0;
    TracedScene direct, tessellated;
    TessellationSummary tessellation;
    double pixel_agreement = 0;          // fraction of pixels where both hit or both miss
    double median_depth_difference = 0;  // |direct − tessellated| view depth over pixels both hit, world units
    Vec3f light;                         // the point light the shadow rays go to
    double secondary_clearance = 0;      // how far the secondary rays start off the direct scene's surface
    SecondaryBenchmark shadow, bounce;
};

// Throws InputError when a scene holds no blob group. `log` receives one line per step.
std::vector<SceneBenchmark> run_blob_benchmark(const BlobBenchmarkSettings& settings,
                                               const std::function<void(const std::string&)>& log);

}  // namespace isotrace::cli
