#pragma once
// Times rays in scenes on a given number of threads, several times: the primary rays (one per pixel centre to its
// first hit, with its view depth: the depth map of renderer/render/depth_map.h) or a fixed list of secondary rays
// (occlusion queries for shadow rays, nearest-hit queries for bounces).
#include <cstdint>
#include <functional>
#include <vector>

#include "renderer/core/ray.h"
#include "renderer/render/depth_map.h"
#include "tools/cli/bench_statistics.h"

namespace isotrace::cli {

struct RayCastTiming {
    int threads = 1;
    std::size_t ray_count = 0;
    std::vector<double> seconds;  // one per run: the time of one pass over the rays
    std::vector<int> passes;      // one per run: how many passes the run took to last its minimum time
    DepthMap depth;               // primary rays, of the last run: which pixels hit, and where
    std::vector<std::uint8_t> hit;  // secondary rays, of the last run: 1 where the ray was occluded / hit

    std::size_t rays() const { return ray_count; }
    double median_seconds() const;
    double mrays_per_second() const { return double(rays()) / median_seconds() * 1e-6; }
    double nanoseconds_per_ray() const { return median_seconds() / double(rays()) * 1e9; }
};

// Runs trace(timing, i) for every i < `scenes`, `repeats` times with the scenes taking turns, each call timed
// inside a TBB arena of `threads` threads (the timing's seconds get one entry per run; trace sets ray_count and
// its results). The other workloads of isotrace bench (path tracing, polygonising) time their runs with it too.
// A run calls trace again until it has lasted `min_run_seconds` (at most kMaxPasses times) and counts the time
// per pass: a run of a millisecond measures a thread pool's wake-up as much as the rays.
constexpr int kMaxPasses = 10000;
std::vector<RayCastTiming> time_taking_turns(std::size_t scenes, int threads, int repeats,
                                             const std::function<void(RayCastTiming&, std::size_t)>& trace,
                                             double min_run_seconds = 0);

// Every timed measurement of isotrace bench starts with this many runs that are not counted: the first finds what
// the rays build as they need it (a deformed superquadric's shell) and fills the caches.
constexpr int kWarmUpRuns = 1;
// Removes the warm-up runs from a timing taken with kWarmUpRuns + repeats runs.
void drop_warm_up(RayCastTiming& timing);

// `repeats` runs of every scene inside a TBB arena of `threads` threads, one timing per scene. Within each repeat
// the scenes take turns, so that a machine whose speed drifts (a shared VM) slows them alike and the ratios of
// run i stay comparable.
std::vector<RayCastTiming> time_primary_rays(const std::vector<const LoadedScene*>& scenes, int threads, int repeats,
                                             double min_run_seconds);

enum class SecondaryQuery { Occlusion, NearestHit };

// The same `rays` traced in every scene with `query`, taking turns as above.
std::vector<RayCastTiming> time_secondary_rays(const std::vector<const LoadedScene*>& scenes,
                                               const std::vector<Ray>& rays, SecondaryQuery query, int threads,
                                               int repeats, double min_run_seconds);

}  // namespace isotrace::cli
