#include "tools/cli/bench_report.h"

#include <cstdio>
#include <filesystem>
#include <thread>

#include "tools/cli/machine_description.h"

namespace isotrace::cli {
namespace {

nlohmann::json runs_json(const std::vector<RayCastTiming>& timings) {
    nlohmann::json runs = nlohmann::json::array();
    for (const RayCastTiming& timing : timings)
        runs.push_back({{"threads", timing.threads},
                        {"median_seconds", timing.median_seconds()},
                        {"seconds", timing.seconds},
                        {"passes", timing.passes},
                        {"mrays_per_second", timing.mrays_per_second()},
                        {"ns_per_ray", timing.nanoseconds_per_ray()}});
    return runs;
}

nlohmann::json traced_json(const TracedScene& traced) {
    return {{"build_seconds", traced.build_seconds},
            {"embree_bytes", traced.embree_bytes},
            {"shape_bytes", traced.shape_bytes},
            {"runs", runs_json(traced.timings)}};
}

// The median over runs of numerator[i] / denominator[i]: runs i of both took turns on the same machine state.
double median_ratio(const std::vector<double>& numerator, const std::vector<double>& denominator) {
    std::vector<double> ratios;
    for (std::size_t i = 0; i < numerator.size() && i < denominator.size(); ++i)
        ratios.push_back(numerator[i] / denominator[i]);
    return median(std::move(ratios));
}

// Adds direct_over_tessellated to every tessellated run.
void add_ratios(nlohmann::json& tessellated_runs, const std::vector<RayCastTiming>& direct,
                const std::vector<RayCastTiming>& tessellated) {
    for (std::size_t i = 0; i < tessellated.size(); ++i)
        tessellated_runs[i]["direct_over_tessellated"] = median_ratio(direct[i].seconds, tessellated[i].seconds);
}

nlohmann::json secondary_json(const SecondaryBenchmark& kind) {
    nlohmann::json result = {{"rays", kind.rays},
                             {"agreement", kind.agreement},
                             {"direct_hit_fraction", kind.direct_hit_fraction},
                             {"direct", {{"runs", runs_json(kind.direct)}}},
                             {"tessellated", {{"runs", runs_json(kind.tessellated)}}}};
    add_ratios(result["tessellated"]["runs"], kind.direct, kind.tessellated);
    return result;
}

// printf into a std::string.
template <class... Args>
std::string format(const char* pattern, Args... args) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, pattern, args...);
    return buffer;
}

std::string scene_name(const nlohmann::json& scene) {
    return std::filesystem::path(scene["scene"].get<std::string>()).stem().string();
}

// One row per thread count of one ray kind: both scenes' speed side by side.
std::string kind_rows(const std::string& scene, const char* kind, std::size_t rays, const nlohmann::json& direct,
                      const nlohmann::json& tessellated, double agreement) {
    if (direct["runs"].empty()) return format("%-12s %-8s %9zu  (no rays to trace)\n", scene.c_str(), kind, rays);
    std::string out;
    for (std::size_t i = 0; i < direct["runs"].size(); ++i) {
        const auto& d = direct["runs"][i];
        const auto& t = tessellated["runs"][i];
        out += i == 0 ? format("%-12s %-8s %9zu", scene.c_str(), kind, rays) : format("%-12s %-8s %9s", "", "", "");
        out += format(" %8d %9.3f %8.0f %9.3f %8.0f %10.1fx", d["threads"].get<int>(),
                      d["mrays_per_second"].get<double>(), d["ns_per_ray"].get<double>(),
                      t["mrays_per_second"].get<double>(), t["ns_per_ray"].get<double>(),
                      t["direct_over_tessellated"].get<double>());
        out += i == 0 ? format(" %8.2f\n", 100 * agreement) : std::string("\n");
    }
    return out;
}

}  // namespace

nlohmann::json benchmark_json(const BlobBenchmarkSettings& settings, const std::vector<SceneBenchmark>& results) {
    nlohmann::json scenes = nlohmann::json::array();
    for (const SceneBenchmark& r : results) {
        nlohmann::json direct = traced_json(r.direct), tessellated = traced_json(r.tessellated);
        direct["bytes_per_element"] = double(r.direct.shape_bytes + std::size_t(r.direct.embree_bytes)) / double(r.elements);
        tessellated["bytes_per_triangle"] =
            double(r.tessellated.shape_bytes + std::size_t(r.tessellated.embree_bytes)) / double(r.tessellation.triangles);
        tessellated["cell_size"] = r.tessellation.cell_size;
        tessellated["tessellation_seconds"] = r.tessellation.seconds;
        tessellated["triangles"] = r.tessellation.triangles;
        tessellated["vertices"] = r.tessellation.vertices;
        tessellated["closed"] = r.tessellation.closed;
        add_ratios(tessellated["runs"], r.direct.timings, r.tessellated.timings);
        scenes.push_back({{"scene", r.scene},
                          {"elements", r.elements},
                          {"rays", r.direct.timings.front().rays()},
                          {"direct", direct},
                          {"tessellated", tessellated},
                          {"pixel_agreement", r.pixel_agreement},
                          {"median_depth_difference", r.median_depth_difference},
                          {"light", {r.light.x, r.light.y, r.light.z}},
                          {"secondary_clearance", r.secondary_clearance},
                          {"shadow", secondary_json(r.shadow)},
                          {"bounce", secondary_json(r.bounce)}});
    }
    nlohmann::json report = {{"repeats", settings.repeats},
                             {"warm_up_runs", kWarmUpRuns},
                             {"min_run_seconds", settings.min_run_seconds},
                             {"threads", settings.threads},
                             {"cells_per_radius", settings.tessellation.cells_per_radius},
                             {"machine", {{"cores", std::thread::hardware_concurrency()}, {"cpu", cpu_model()}}},
                             {"scenes", scenes}};
    report["resolution"] = settings.resolution
                               ? nlohmann::json::array({settings.resolution->width, settings.resolution->height})
                               : nlohmann::json();
    report["cell_size"] =
        settings.tessellation.cell_size ? nlohmann::json(*settings.tessellation.cell_size) : nlohmann::json();
    return report;
}

std::string benchmark_table(const nlohmann::json& report) {
    std::string out = format("Primary, shadow and bounce rays; medians of %d run(s); %u cores, %s\n\n",
                             report["repeats"].get<int>(), report["machine"]["cores"].get<unsigned>(),
                             report["machine"]["cpu"].get<std::string>().c_str());
    out += "Direct: the scene's implicit shapes as Embree user geometry; an element is a blob element, isosurface,\n"
           "superquadric, CSG solid, torus, cylinder or cone (primary rays)\n";
    out += format("%-12s %9s %9s %9s %12s %8s %9s %10s\n", "scene", "elements", "rays", "build ms", "bytes/elem",
                  "threads", "Mrays/s", "ns/ray");
    for (const auto& s : report["scenes"]) {
        const auto& d = s["direct"];
        bool first = true;
        for (const auto& run : d["runs"]) {
            if (first)
                out += format("%-12s %9zu %9zu %9.1f %12.0f", scene_name(s).c_str(), s["elements"].get<std::size_t>(),
                              s["rays"].get<std::size_t>(), d["build_seconds"].get<double>() * 1e3,
                              d["bytes_per_element"].get<double>());
            else
                out += format("%-12s %9s %9s %9s %12s", "", "", "", "", "");
            out += format(" %8d %9.3f %10.0f\n", run["threads"].get<int>(), run["mrays_per_second"].get<double>(),
                          run["ns_per_ray"].get<double>());
            first = false;
        }
    }
    out += "\nTessellated: the polygoniser's mesh traced natively by Embree (primary rays: same camera, same rays)\n";
    out += format("%-12s %8s %10s %8s %9s %10s %8s %9s %8s %11s %8s %11s\n", "scene", "cell", "triangles", "tess s",
                  "build ms", "bytes/tri", "threads", "Mrays/s", "ns/ray", "direct/tess", "agree %",
                  "depth diff");
    for (const auto& s : report["scenes"]) {
        const auto& t = s["tessellated"];
        bool first = true;
        for (const auto& run : t["runs"]) {
            if (first)
                out += format("%-12s %8.4f %10zu %8.2f %9.1f %10.0f", scene_name(s).c_str(), t["cell_size"].get<double>(),
                              t["triangles"].get<std::size_t>(), t["tessellation_seconds"].get<double>(),
                              t["build_seconds"].get<double>() * 1e3, t["bytes_per_triangle"].get<double>());
            else
                out += format("%-12s %8s %10s %8s %9s %10s", "", "", "", "", "", "");
            out += format(" %8d %9.3f %8.0f %10.1fx", run["threads"].get<int>(), run["mrays_per_second"].get<double>(),
                          run["ns_per_ray"].get<double>(), run["direct_over_tessellated"].get<double>());
            out += first ? format(" %8.2f %11.2g\n", 100 * s["pixel_agreement"].get<double>(),
                                  s["median_depth_difference"].get<double>())
                         : std::string("\n");
            first = false;
        }
        if (!t["closed"].get<bool>()) out += "  warning: the tessellation is not closed and consistently oriented\n";
    }
    out += "\nPer ray kind, the same rays in both scenes: primary (one per pixel centre), shadow (from every\n"
           "primary hit of the direct scene facing a point light above the scene) and bounce (one cosine-distributed\n"
           "direction per primary hit, nearest hit), starting half a tessellation cell off the surface;\n"
           "agree %: same hit/miss or occluded answer in both scenes\n";
    const char* const header = "%-12s %-8s %9s %8s %9s %8s %9s %8s %11s %8s\n";
    out += format(header, "scene", "kind", "rays", "threads", "direct", "ns/ray", "tess", "ns/ray", "direct/tess",
                  "agree %");
    out += format(header, "", "", "", "", "Mrays/s", "", "Mrays/s", "", "", "");
    for (const auto& s : report["scenes"]) {
        const std::string name = scene_name(s);
        out += kind_rows(name, "primary", s["rays"].get<std::size_t>(), s["direct"], s["tessellated"],
                         s["pixel_agreement"].get<double>());
        for (const char* kind : {"shadow", "bounce"})
            out += kind_rows(name, kind, s[kind]["rays"].get<std::size_t>(), s[kind]["direct"], s[kind]["tessellated"],
                             s[kind]["agreement"].get<double>());
    }
    const auto& scenes = report["scenes"];
    if (scenes.size() > 1) {
        const double first = scenes.front()["direct"]["runs"][0]["ns_per_ray"].get<double>();
        const double last = scenes.back()["direct"]["runs"][0]["ns_per_ray"].get<double>();
        out += format("\nTime per ray (direct, %d thread(s)) from %s to %s: %.2fx\n",
                      scenes.front()["direct"]["runs"][0]["threads"].get<int>(), scene_name(scenes.front()).c_str(),
                      scene_name(scenes.back()).c_str(), last / first);
    }
    return out;
}

}  // namespace isotrace::cli
