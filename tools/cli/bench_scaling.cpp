#include "tools/cli/bench_scaling.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "renderer/scene/loaded_scene.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/ray_cast_timing.h"

namespace isotrace::cli {
namespace {

// Removes the generated scene file however the load ends.
struct TemporaryFile {
    std::filesystem::path path;
    ~TemporaryFile() {
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
    }
};

nlohmann::json scaled(std::initializer_list<double> point, double scale) {
    nlohmann::json values = nlohmann::json::array();
    for (double v : point) values.push_back(v * scale);
    return values;
}

}  // namespace

std::vector<std::size_t> scaling_counts(std::size_t max_elements) {
    std::vector<std::size_t> counts;
    for (std::size_t count = 1000; count <= std::max<std::size_t>(max_elements, 1000); count *= 10)
        counts.push_back(count);
    return counts;
}

std::string scaling_scene(std::size_t elements, const RasterSize& resolution) {
    const double s = std::cbrt(double(elements) / 1000.0);  // blobs_1k's box grown to keep the density
    const nlohmann::json scene = {
        {"isotrace", 1},
        {"description", "isotrace bench --scaling: " + std::to_string(elements) + " blobs at blobs_1k's density"},
        {"film", {{"resolution", {resolution.width, resolution.height}}, {"spp", 1}}},
        {"camera",
         {{"type", "perspective"},
          {"fov", 40},
          {"look_at", {{"eye", scaled({0, 4, 11}, s)}, {"target", scaled({0, 2, 0}, s)}, {"up", {0, 1, 0}}}}}},
        {"integrator", {{"type", "aov"}, {"aov", "normal"}}},
        {"materials", {{"blob", {{"type", "diffuse"}, {"reflectance", 0.7}}}}},
        {"lights", nlohmann::json::array()},
        {"objects",
         {{{"name", "cloud"},
           {"material", "blob"},
           {"shape",
            {{"type", "blobs"},
             {"field", "kim"},
             {"threshold", 0.5},
             {"generate",
              {{"count", elements},
               {"seed", 7},
               {"min", scaled({-2, 0.3, -2}, s)},
               {"max", scaled({2, 3.7, 2}, s)},
               {"radius", {0.387798, 0.64633}},
               {"weight", {0.8, 1.2}}}}}}}}}};
    return scene.dump(2) + "\n";
}

std::vector<ScalingPoint> run_scaling(const std::vector<std::size_t>& counts, const RasterSize& resolution,
                                      int threads, int repeats, double min_run_seconds,
                                      const std::function<void(const std::string&)>& log) {
    std::vector<ScalingPoint> points;
    for (std::size_t count : counts) {
        log("scaling: " + std::to_string(count) + " elements");
        const TemporaryFile file{std::filesystem::temp_directory_path() /
                                 ("isotrace-bench-" + std::to_string(getpid()) + "-" + std::to_string(count) + ".json")};
        write_text_output(file.path.string(), scaling_scene(count, resolution));
        const std::unique_ptr<LoadedScene> scene = load_scene(file.path.string());
        RayCastTiming timing = time_primary_rays({scene.get()}, threads, kWarmUpRuns + repeats, min_run_seconds).front();
        drop_warm_up(timing);
        const BuildStatistics& build = scene->scene->build_statistics();
        ScalingPoint point;
        point.elements = count;
        point.rays = timing.rays();
        point.build_seconds = build.seconds;
        point.bytes_per_element = double(std::max<std::int64_t>(build.embree_bytes, 0) + std::int64_t(build.shape_bytes)) /
                                  double(count);
        point.nanoseconds_per_ray = timing.nanoseconds_per_ray();
        point.cost_growth = points.empty() ? 1 : point.nanoseconds_per_ray / points.front().nanoseconds_per_ray;
        points.push_back(point);
    }
    return points;
}

}  // namespace isotrace::cli
