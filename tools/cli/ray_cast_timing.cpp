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

RayCastTiming time_primary_rays(const LoadedScene& scene, int threads, int repeats) {
    RayCastTiming timing;
    timing.threads = threads;
    tbb::task_arena arena(threads);
    std::vector<double> seconds;
    for (int run = 0; run < repeats; ++run) {
        const auto start = std::chrono::steady_clock::now();
        timing.depth = arena.execute([&] { return render_depth_map(scene); });
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    timing.median_seconds = median(seconds);
    return timing;
}

}  // namespace isotrace::cli
