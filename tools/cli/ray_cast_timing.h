#pragma once
// Times the primary rays of scenes (one per pixel centre to its first hit, with its view depth: the depth map of
// renderer/render/depth_map.h) on a given number of threads, several times.
#include <vector>

#include "renderer/render/depth_map.h"

namespace isotrace::cli {

struct RayCastTiming {
    int threads = 1;
    std::vector<double> seconds;  // one per run
    DepthMap depth;               // of the last run: which pixels hit, and where

    std::size_t rays() const { return depth.depth.size(); }
    double median_seconds() const;
    double mrays_per_second() const { return double(rays()) / median_seconds() * 1e-6; }
    double nanoseconds_per_ray() const { return median_seconds() / double(rays()) * 1e9; }
};

// `repeats` runs of every scene inside a TBB arena of `threads` threads, one timing per scene. Within each repeat
// the scenes take turns, so that a machine whose speed drifts (a shared VM) slows them alike and the ratios of
// run i stay comparable.
std::vector<RayCastTiming> time_primary_rays(const std::vector<const LoadedScene*>& scenes, int threads, int repeats);

double median(std::vector<double> values);

}  // namespace isotrace::cli
