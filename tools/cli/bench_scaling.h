#pragma once
// isotrace bench --scaling: how the cost of a primary ray and the memory per element grow with the number of
// blob elements, at a fixed density. Each count's scene is generated on the fly (the blobs_1k scene's
// generator, radii and camera, with the box and the view scaled by (count / 1000)^(1/3) so that the elements
// per unit volume stay the same), written to a temporary file, loaded and traced.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "renderer/plugin/camera.h"

namespace isotrace::cli {

struct ScalingPoint {
    std::size_t elements = 0;
    std::size_t rays = 0;
    double build_seconds = 0;
    double bytes_per_element = 0;      // Embree's and the shapes' memory over the element count
    double nanoseconds_per_ray = 0;    // median over the runs
    double cost_growth = 1;            // ns per ray over that of the smallest count
};

// The counts 1k, 10k, ... up to `max_elements` (at least 1000).
std::vector<std::size_t> scaling_counts(std::size_t max_elements);

// The generated scene of `elements` blobs (JSON text in the scene format).
std::string scaling_scene(std::size_t elements, const RasterSize& resolution);

// Times primary rays on `threads` threads, warm-up plus `repeats` runs per count, each run at least
// `min_run_seconds` long (time_taking_turns).
std::vector<ScalingPoint> run_scaling(const std::vector<std::size_t>& counts, const RasterSize& resolution,
                                      int threads, int repeats, double min_run_seconds,
                                      const std::function<void(const std::string&)>& log);

}  // namespace isotrace::cli
