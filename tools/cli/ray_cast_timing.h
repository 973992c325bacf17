#pragma once
// Times the primary rays of a scene (one per pixel centre to its first hit, with its view depth: the depth map
// of renderer/render/depth_map.h) on a given number of threads, several times, and keeps the median.
#include <vector>

#include "renderer/render/depth_map.h"

namespace isotrace::cli {

struct RayCastTiming {
    int threads = 1;
    double median_seconds = 0;
    DepthMap depth;  // of the last run: which pixels hit, and where

    std::size_t rays() const { return depth.depth.size(); }
    double mrays_per_second() const { return double(rays()) / median_seconds * 1e-6; }
    double nanoseconds_per_ray() const { return median_seconds / double(rays()) * 1e9; }
};

// `repeats` runs inside a TBB arena of `threads` threads.
RayCastTiming time_primary_rays(const LoadedScene& scene, int threads, int repeats);

double median(std::vector<double> values);

}  // namespace isotrace::cli
