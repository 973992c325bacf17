#include "tools/cli/ray_cast_timing.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>

namespace isotrace::cli {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    if (n == 0) return 0;
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double RayCastTiming::median_seconds() const { return median(seconds); }

std::vector<RayCastTiming> time_primary_rays(const std::vector<const LoadedScene*>& scenes, int threads, int repeats) {
    std::vector<RayCastTiming> timings(scenes.size());
    for (RayCastTiming& timing : timings) timing.threads = threads;
    tbb::task_arena arena(threads);
    for (int run = 0; run < repeats; ++run)
        for (std::size_t i = 0; i < scenes.size(); ++i) {
            const auto start = std::chrono::steady_clock::now();
            timings[i].depth = arena.execute([&] { return render_depth_map(*scenes[i]); });
            timings[i].seconds.push_back(
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
    return timings;
}

}  // namespace isotrace::cli
