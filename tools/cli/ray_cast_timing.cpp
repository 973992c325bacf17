#include "tools/cli/ray_cast_timing.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <functional>

#include "renderer/core/parallel_for.h"
#include "renderer/embree/embree_device.h"

namespace isotrace::cli {

std::vector<RayCastTiming> time_taking_turns(std::size_t scenes, int threads, int repeats,
                                             const std::function<void(RayCastTiming&, std::size_t)>& trace,
                                             double min_run_seconds) {
    std::vector<RayCastTiming> timings(scenes);
    for (RayCastTiming& timing : timings) timing.threads = threads;
    tbb::task_arena arena(threads);
    for (int run = 0; run < repeats; ++run)
        for (std::size_t i = 0; i < scenes; ++i) {
            const auto start = std::chrono::steady_clock::now();
            int passes = 0;
            double seconds = 0;
            do {
                arena.execute([&] { trace(timings[i], i); });
                ++passes;
                seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            } while (seconds < min_run_seconds && passes < kMaxPasses);
            timings[i].seconds.push_back(seconds / passes);
            timings[i].passes.push_back(passes);
        }
    return timings;
}

double RayCastTiming::median_seconds() const { return median(seconds); }

void drop_warm_up(RayCastTiming& timing) {
    timing.seconds.erase(timing.seconds.begin(), timing.seconds.begin() + kWarmUpRuns);
    timing.passes.erase(timing.passes.begin(), timing.passes.begin() + kWarmUpRuns);
}

std::vector<RayCastTiming> time_primary_rays(const std::vector<const LoadedScene*>& scenes, int threads, int repeats,
                                             double min_run_seconds) {
    return time_taking_turns(
        scenes.size(), threads, repeats,
        [&](RayCastTiming& timing, std::size_t i) {
            timing.depth = render_depth_map(*scenes[i]);
            timing.ray_count = timing.depth.depth.size();
        },
        min_run_seconds);
}

std::vector<RayCastTiming> time_secondary_rays(const std::vector<const LoadedScene*>& scenes,
                                               const std::vector<Ray>& rays, SecondaryQuery query, int threads,
                                               int repeats, double min_run_seconds) {
    constexpr std::size_t kRaysPerTask = 256;  // like a row of the depth map: enough work to amortise a task
    return time_taking_turns(scenes.size(), threads, repeats, [&](RayCastTiming& timing, std::size_t i) {
        const RenderScene& scene = *scenes[i]->scene;
        timing.ray_count = rays.size();
        timing.hit.assign(rays.size(), 0);
        parallel_for(std::size_t(0), (rays.size() + kRaysPerTask - 1) / kRaysPerTask, [&](std::size_t task) {
            enable_flush_to_zero();  // as in every render thread
            const std::size_t end = std::min(rays.size(), (task + 1) * kRaysPerTask);
            for (std::size_t r = task * kRaysPerTask; r < end; ++r)
                timing.hit[r] = query == SecondaryQuery::Occlusion
                                    ? scene.occluded(rays[r])
                                    : scene.intersect(rays[r], RayKind::Secondary).has_value();
        });
    }, min_run_seconds);
}

}  // namespace isotrace::cli
