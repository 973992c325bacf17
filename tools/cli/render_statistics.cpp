#include "tools/cli/render_statistics.h"

#include <cstdio>
#include <sstream>

#include "tools/cli/peak_memory.h"

namespace isotrace::cli {

nlohmann::json render_statistics(const LoadedScene& scene, const RenderResult& result, const CounterTotals& counts,
                                 const PhaseTimes& times, int threads, const BeautyCheck& beauty) {
    const double pixel_samples = double(scene.film.crop.area()) * double(result.completed_spp);
    const double render_seconds = times.render > 0 ? times.render : 1e-12;
    nlohmann::json stats;
    stats["scene"] = scene.path;
    stats["integrator"] = scene.integrator_type;
    stats["sampler"] = scene.sampler_type;
    stats["seed"] = scene.seed;
    stats["threads"] = threads;
    stats["packets"] = scene.integrator->packet_description(*scene.scene);
    stats["spp"] = result.completed_spp;
    stats["spp_max"] = result.max_spp;
    stats["spp_requested"] = scene.spp;
    stats["passes"] = result.passes;
    stats["partial"] = result.partial;
    stats["cancelled"] = result.cancelled;
    stats["resolution"] = {scene.film.raster.width, scene.film.raster.height};
    stats["pixels_rendered"] = scene.film.crop.area();
    stats["parse_seconds"] = times.parse;
    stats["build_seconds"] = times.build;
    stats["render_seconds"] = times.render;
    stats["write_seconds"] = times.write;
    stats["rays_total"] = counts.total_rays();
    stats["camera_rays"] = counts.camera_rays;
    stats["secondary_rays"] = counts.secondary_rays;
    stats["shadow_rays"] = counts.shadow_rays;
    stats["mrays_per_second"] = double(counts.total_rays()) / render_seconds * 1e-6;
    stats["samples_per_second"] = pixel_samples / render_seconds;
    stats["nan_samples"] = counts.nan_samples;
    stats["non_finite_pixels"] = beauty.non_finite_pixels;
    stats["peak_memory_bytes"] = peak_memory_bytes();
    const BuildStatistics& build = scene.scene->build_statistics();
    stats["objects"] = build.objects;
    stats["instanced_objects"] = build.instanced_objects;
    stats["placements"] = build.placements;
    stats["placed_shapes"] = build.placed_shapes;
    stats["object_bytes"] = build.object_bytes;
    stats["embree_bytes"] = build.embree_bytes;
    stats["shape_bytes"] = build.shape_bytes;
    nlohmann::json geometry = nlohmann::json::object();
    for (const auto& [type, c] : counts.geometry) {
        nlohmann::json row;
        row["primitives"] = build.primitives_by_type.count(type) ? build.primitives_by_type.at(type) : 0;
        row["intersection_tests"] = c.counts_tests ? nlohmann::json(c.tests) : nlohmann::json(nullptr);
        row["candidate_hits"] = c.counts_tests ? nlohmann::json(c.candidate_hits) : nlohmann::json(nullptr);
        row["closest_hits"] = c.closest_hits;
        geometry[type] = row;
    }
    stats["geometry"] = geometry;
    stats["counters"] = counts.named;
    return stats;
}

namespace {

// The lines of both levels: phases, speed, NaNs and memory.
void format_summary(const nlohmann::json& s, std::ostringstream& out) {
    char line[256];
    std::snprintf(line, sizeof line, "  time      parse %.3f s | build %.3f s | render %.3f s | write %.3f s\n",
                  s["parse_seconds"].get<double>(), s["build_seconds"].get<double>(),
                  s["render_seconds"].get<double>(), s["write_seconds"].get<double>());
    out << line;
    std::snprintf(line, sizeof line, "  samples   %d spp x %lld pixels, %.3g samples/s, %.2f Mrays/s, %d thread(s)%s\n",
                  s["spp"].get<int>(), s["pixels_rendered"].get<long long>(), s["samples_per_second"].get<double>(),
                  s["mrays_per_second"].get<double>(), s["threads"].get<int>(),
                  s["partial"].get<bool>() ? " (partial)" : "");
    out << line;
    std::snprintf(line, sizeof line, "  NaN/Inf   %llu samples discarded, %llu pixels in the image\n",
                  s["nan_samples"].get<unsigned long long>(), s["non_finite_pixels"].get<unsigned long long>());
    out << line;
    std::snprintf(line, sizeof line, "  memory    %.1f MiB peak resident\n",
                  double(s["peak_memory_bytes"].get<unsigned long long>()) / (1 << 20));
    out << line;
    if (s.contains("placements") && s["placements"].get<unsigned long long>() > 0) {
        std::snprintf(line, sizeof line,
                      "  instances %llu placement(s) of %llu shape(s); %.1f MiB in Embree, %.1f MiB in shapes, "
                      "%.1f MiB in objects\n",
                      s["placements"].get<unsigned long long>(), s["placed_shapes"].get<unsigned long long>(),
                      double(s["embree_bytes"].get<long long>()) / (1 << 20),
                      double(s["shape_bytes"].get<unsigned long long>()) / (1 << 20),
                      double(s["object_bytes"].get<unsigned long long>()) / (1 << 20));
        out << line;
    }
}

}  // namespace

std::string format_statistics(const nlohmann::json& s, StatisticsDetail detail) {
    if (detail == StatisticsDetail::None) return "";
    std::ostringstream out;
    out << "statistics:\n";
    format_summary(s, out);
    if (detail == StatisticsDetail::Short) return out.str();
    char line[256];
    if (s.contains("packets") && !s["packets"].get<std::string>().empty())
        out << "  packets   " << s["packets"].get<std::string>() << "\n";
    std::snprintf(line, sizeof line, "  rays      %llu total (%llu camera, %llu secondary, %llu shadow)\n",
                  s["rays_total"].get<unsigned long long>(), s["camera_rays"].get<unsigned long long>(),
                  s["secondary_rays"].get<unsigned long long>(), s["shadow_rays"].get<unsigned long long>());
    out << line;
    out << "  geometry  type             primitives   int. tests   cand. hits  closest hits\n";
    for (const auto& [type, row] : s["geometry"].items()) {
        const auto number_or_dash = [](const nlohmann::json& v) {
            return v.is_null() ? std::string("-") : std::to_string(v.get<unsigned long long>());
        };
        std::snprintf(line, sizeof line, "            %-16s %10llu %12s %12s %13llu\n", type.c_str(),
                      row["primitives"].get<unsigned long long>(), number_or_dash(row["intersection_tests"]).c_str(),
                      number_or_dash(row["candidate_hits"]).c_str(), row["closest_hits"].get<unsigned long long>());
        out << line;
    }
    // Named counters "owner.what" (owner: a geometry type, or a type and object as in "blobs[cloud]"): one line
    // per owner.
    std::string owner_on_line;
    for (const auto& [name, value] : s["counters"].items()) {
        const std::size_t dot = name.rfind('.');
        const std::string owner = dot == std::string::npos ? name : name.substr(0, dot);
        const std::string what = dot == std::string::npos ? "count" : name.substr(dot + 1);
        if (owner != owner_on_line) {
            out << (owner_on_line.empty() ? "  counters  " : "\n            ") << owner << ":";
            owner_on_line = owner;
        }
        out << " " << what << " " << value.get<unsigned long long>();
    }
    if (!owner_on_line.empty()) out << "\n";
    if (s.contains("ranks")) {  // a distributed render (docs/distributed.md)
        for (const nlohmann::json& rank : s["ranks"]) {
            std::snprintf(line, sizeof line, "  %s %-4d %s: %llu items, %llu samples, %.3g rays, %.2f Mrays/s over %.3f s busy\n",
                          rank["rank"].get<int>() == 0 ? "ranks    " : "         ", rank["rank"].get<int>(),
                          rank["host"].get<std::string>().c_str(), rank["items"].get<unsigned long long>(),
                          rank["samples"].get<unsigned long long>(), double(rank["rays"].get<unsigned long long>()),
                          rank["mrays_per_second"].get<double>(), rank["busy_seconds"].get<double>());
            out << line;
        }
    }
    return out.str();
}

}  // namespace isotrace::cli
