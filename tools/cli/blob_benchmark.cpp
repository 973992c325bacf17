#include "tools/cli/blob_benchmark.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "geometry/implicit/blob_group_shape.h"
#include "geometry/mesh/triangle_mesh_shape.h"
#include "geometry/polygonize/mesh_topology.h"
#include "geometry/polygonize/polygonize_field.h"
#include "renderer/core/input_error.h"
#include "tools/cli/secondary_ray_lists.h"

namespace isotrace::cli {
namespace {

TracedScene build_of(const LoadedScene& scene) {
    const BuildStatistics& build = scene.scene->build_statistics();
    TracedScene traced;
    traced.build_seconds = build.seconds;
    traced.embree_bytes = build.embree_bytes;
    traced.shape_bytes = build.shape_bytes;
    return traced;
}

// The shapes the comparison replaces by their tessellation: the implicit surfaces isotrace traces directly, and the
// round primitives (an open cylinder or cone, which has no inside, stays as it is in both scenes).
constexpr std::array<const char*, 7> kTessellatedTypes = {"blobs", "isosurface", "superquadric", "csg",
                                                          "torus", "cylinder", "cone"};

bool is_tessellated(const Shape& shape) {
    return std::find_if(kTessellatedTypes.begin(), kTessellatedTypes.end(),
                        [&](const char* type) { return shape.type_name() == type; }) != kTessellatedTypes.end();
}

// A field's lattice: `cell` (--cell-size) or 2⁷ cells along the longest side of its bounds.
int lattice_depth(const ImplicitField& field, const std::optional<double>& cell) {
    const FieldBox box = field.bounds();
    if (!cell) return 7;
    const double longest = max_component(box.upper - box.lower);
    return std::clamp(int(std::ceil(std::log2(longest / *cell))), 1, kMaxPolygonizeDepth);
}

// Replaces every blob group, isosurface, superquadric, CSG solid, torus and closed cylinder and cone by its
// tessellation as the scene loads, timing the polygoniser: blob groups by their own tessellator, the others by dual
// contouring of their field.
// `cells` receives each tessellation's cell size, in its shape's own space, by the mesh that replaces the shape.
std::function<std::unique_ptr<Shape>(std::unique_ptr<Shape>)> tessellate_blob_groups(
    const BlobBenchmarkSettings& settings, const std::string& scene, TessellationSummary& summary,
    std::unordered_map<const Shape*, double>& cells) {
    return [&settings, scene, &summary, &cells](std::unique_ptr<Shape> shape) -> std::unique_ptr<Shape> {
        if (!is_tessellated(*shape)) return shape;
        const auto start = std::chrono::steady_clock::now();
        double cell = 0;
        TriangleMeshData mesh;
        if (const auto* blobs = dynamic_cast<const BlobGroupShape*>(shape.get())) {
            cell = settings.tessellation.cell_size_for(blobs->group());
            mesh = tessellate(blobs->group(), cell, scene);
        } else {
            std::unique_ptr<ImplicitField> field;
            try {
                field = shape->implicit_field();
            } catch (const std::invalid_argument&) {
                return shape;  // a surface without an inside
            }
            PolygonizeOptions options;
            options.depth = lattice_depth(*field, settings.tessellation.cell_size);
            cell = max_component(field->bounds().upper - field->bounds().lower) / double(1 << options.depth);
            mesh = std::move(polygonize_field(*field, options).mesh);
        }
        summary.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (mesh.triangles.empty())
            throw InputError({}, scene, "a " + std::string(shape->type_name()) + " shape has no surface to tessellate");
        summary.triangles += mesh.triangles.size();
        summary.vertices += mesh.positions.size();
        summary.closed = summary.closed && is_closed_and_consistently_oriented(mesh);
        auto tessellation = std::make_unique<TriangleMeshShape>(std::move(mesh));
        cells[tessellation.get()] = cell;
        return tessellation;
    };
}

// The finest and coarsest tessellation cells in the world: a cell's longest edge once its object's transform (or a
// placement's) has carried it there, so that a scaled object's cells are as large as they are drawn.
void measure_world_cells(const RenderScene& scene, const std::unordered_map<const Shape*, double>& cells,
                         TessellationSummary& summary) {
    bool first = true;
    for (std::uint32_t id = 0; id < scene.object_count(); ++id) {
        const SceneObject object = scene.object(id);
        const auto found = cells.find(object.shape.get());
        if (found == cells.end()) continue;
        double longest = 0;
        for (const Vec3d& axis : {Vec3d{1, 0, 0}, Vec3d{0, 1, 0}, Vec3d{0, 0, 1}})
            longest = std::max(longest, length(object.to_world.vector(axis)));
        const double cell = found->second * longest;
        summary.cell_size = first ? cell : std::min(summary.cell_size, cell);
        summary.coarsest_cell = std::max(summary.coarsest_cell, cell);
        first = false;
    }
}

void compare_images(const DepthMap& direct, const DepthMap& tessellated, SceneBenchmark& result) {
    std::size_t agree = 0;
    std::vector<double> differences;
    for (std::size_t i = 0; i < direct.depth.size(); ++i) {
        const bool hit_direct = std::isfinite(direct.depth[i]), hit_tessellated = std::isfinite(tessellated.depth[i]);
        if (hit_direct == hit_tessellated) ++agree;
        if (hit_direct && hit_tessellated) differences.push_back(std::abs(direct.depth[i] - tessellated.depth[i]));
    }
    result.pixel_agreement = direct.depth.empty() ? 1.0 : double(agree) / double(direct.depth.size());
    result.median_depth_difference = median(std::move(differences));
}

void compare_answers(SecondaryBenchmark& kind) {
    if (kind.rays == 0) return;
    const std::vector<std::uint8_t>& direct = kind.direct.front().hit;
    const std::vector<std::uint8_t>& tessellated = kind.tessellated.front().hit;
    std::size_t agree = 0, hits = 0;
    for (std::size_t i = 0; i < direct.size(); ++i) {
        agree += direct[i] == tessellated[i];
        hits += direct[i];
    }
    kind.agreement = double(agree) / double(direct.size());
    kind.direct_hit_fraction = double(hits) / double(direct.size());
}

void time_secondary_kind(const std::vector<const LoadedScene*>& scenes, const std::vector<Ray>& rays,
                         SecondaryQuery query, int threads, const BlobBenchmarkSettings& settings,
                         SecondaryBenchmark& kind) {
    kind.rays = rays.size();
    if (rays.empty()) return;  // nothing to time: no runs
    std::vector<RayCastTiming> timings =
        time_secondary_rays(scenes, rays, query, threads, kWarmUpRuns + settings.repeats, settings.min_run_seconds);
    for (RayCastTiming& timing : timings) drop_warm_up(timing);
    kind.direct.push_back(std::move(timings[0]));
    kind.tessellated.push_back(std::move(timings[1]));
}

}  // namespace

std::vector<SceneBenchmark> run_blob_benchmark(const BlobBenchmarkSettings& settings,
                                               const std::function<void(const std::string&)>& log) {
    std::vector<SceneBenchmark> results;
    for (const std::string& path : settings.scenes) {
        SceneBenchmark result;
        result.scene = path;
        SceneOverrides overrides;
        if (settings.resolution) overrides.settings.push_back(resolution_setting(*settings.resolution));
        log(path + ": loading");
        const std::unique_ptr<LoadedScene> direct = load_scene(path, overrides);
        const auto& primitives = direct->scene->build_statistics().primitives_by_type;
        for (const char* type : kTessellatedTypes)
            if (const auto found = primitives.find(type); found != primitives.end()) result.elements += found->second;
        if (result.elements == 0)
            throw InputError({}, path,
                             "the scene has no blob group, isosurface, superquadric, CSG solid, torus, cylinder or "
                             "cone to benchmark");
        log(path + ": loading again and tessellating");
        std::unordered_map<const Shape*, double> cells;
        overrides.replace_shape = tessellate_blob_groups(settings, path, result.tessellation, cells);
        const std::unique_ptr<LoadedScene> tessellated = load_scene(path, overrides);
        measure_world_cells(*tessellated->scene, cells, result.tessellation);
        result.direct = build_of(*direct);
        result.tessellated = build_of(*tessellated);
        log(path + ": building the shadow and bounce rays from the direct scene's primary hits");
        result.secondary_clearance = kSecondaryClearanceInCells * result.tessellation.coarsest_cell;
        const SecondaryRayLists secondary = build_secondary_rays(*direct, float(result.secondary_clearance));
        result.light = secondary.light;
        const std::vector<const LoadedScene*> scenes = {direct.get(), tessellated.get()};
        for (int threads : settings.threads) {
            log(path + ": " + std::to_string(settings.repeats) + " run(s) each on " + std::to_string(threads) +
                " thread(s)");
            std::vector<RayCastTiming> timings =
                time_primary_rays(scenes, threads, kWarmUpRuns + settings.repeats, settings.min_run_seconds);
            for (RayCastTiming& timing : timings) drop_warm_up(timing);
            result.direct.timings.push_back(std::move(timings[0]));
            result.tessellated.timings.push_back(std::move(timings[1]));
            time_secondary_kind(scenes, secondary.shadow, SecondaryQuery::Occlusion, threads, settings, result.shadow);
            time_secondary_kind(scenes, secondary.bounce, SecondaryQuery::NearestHit, threads, settings, result.bounce);
        }
        compare_images(result.direct.timings.front().depth, result.tessellated.timings.front().depth, result);
        compare_answers(result.shadow);
        compare_answers(result.bounce);
        results.push_back(std::move(result));
    }
    return results;
}

}  // namespace isotrace::cli
