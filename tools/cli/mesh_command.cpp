// isotrace mesh: one implicit object of a scene polygonised by marching cubes, octree dual contouring or
// spherical-octree dual contouring, written as PLY or OBJ, with counts, time and the distance to the true surface.
// With --method traced, an object that is traced as triangles (meshes, abm_patch tessellations, sweep tubes) is
// written as traced, in world space.
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "geometry/mesh/triangle_mesh_shape.h"
#include "geometry/polygonize/mesh_error.h"
#include "geometry/polygonize/polygonize_field.h"
#include "renderer/core/input_error.h"
#include "renderer/core/lower_extension.h"
#include "renderer/scene/loaded_scene.h"
#include "renderer/core/printable.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/commands.h"
#include "tools/cli/obj_writer.h"
#include "tools/cli/object_field.h"
#include "tools/cli/ply_writer.h"
#include "tools/cli/thread_limit.h"
#include "tools/cli/memory_limit_option.h"
#include "tools/cli/scene_options.h"

namespace isotrace::cli {
namespace {

struct MeshArguments {
    std::string scene, object, output, max_memory;
    std::string method = "dc";
    int depth = 6;
    std::vector<double> origin;
    std::optional<double> simplify;
    std::string pole_cap;  // empty: not given
    bool no_origin_correction = false;
    std::size_t error_samples = 20000;
    int threads = 0;
    bool quiet = false;
    SceneOptions scene_options;
};

struct ObjectField {
    SceneObject object;
    std::unique_ptr<ImplicitField> field;
};

// Without --object: the scene's one object with an implicit surface (a blob group next to a floor mesh, say),
// with the field found while looking for it.
ObjectField only_implicit_object(const RenderScene& scene, const std::string& file) {
    std::vector<ObjectField> implicit;
    std::vector<std::string> names;
    for (std::uint32_t id = 0; id < scene.object_count(); ++id) {
        SceneObject object = scene.object(id);
        std::unique_ptr<ImplicitField> field;
        try {
            field = object.shape->implicit_field();
        } catch (const std::invalid_argument&) {
            continue;  // an open mesh, say: no inside to mesh
        }
        if (!field) continue;
        names.push_back(object.name);
        implicit.push_back({std::move(object), std::move(field)});
    }
    if (implicit.size() == 1) {
        ObjectField& only = implicit.front();
        only.field = placed(only.object, std::move(only.field));
        return std::move(only);
    }
    throw InputError({}, "--object",
                     implicit.empty() ? file + " has no object with an implicit surface"
                                      : file + " has several objects with an implicit surface (" + joined_names(names) +
                                            "): name one with --object");
}

PolygonizeOptions options_from(const MeshArguments& args) {
    PolygonizeOptions options;
    const auto method = polygonize_method_named(args.method);
    if (!method) throw InputError({}, "--method", "unknown method \"" + args.method + "\"; expected mc, dc, sdc or traced");
    options.method = *method;
    options.depth = args.depth;
    if (!args.pole_cap.empty()) {
        options.pole_cap = pole_cap_named(args.pole_cap);
        if (!options.pole_cap)
            throw InputError({}, "--pole-cap", "unknown placement \"" + args.pole_cap + "\"; expected axis, normal or vertical");
    }
    options.correct_origin = !args.no_origin_correction;
    options.simplify = args.simplify;
    if (!args.origin.empty()) {
        if (args.origin.size() != 3) throw InputError({}, "--origin", "expected x,y,z");
        options.origin = Vec3d{args.origin[0], args.origin[1], args.origin[2]};
    }
    return options;
}

void write_mesh(const std::string& path, const std::string& extension, const std::string& name, const TriangleMeshData& mesh) {
    if (extension == ".obj") write_obj(path, {{name, mesh}});
    else write_ply(path, mesh);
}

int run_mesh(const MeshArguments& args) {
    const std::string extension = lower_extension(args.output);
    require_extension(args.output, extension == ".obj" ? ".obj" : ".ply", "--output");
    check_output_paths({{args.output, "--output"}}, {{args.scene, "the scene"}});
    const bool traced = args.method == "traced";
    const std::optional<PolygonizeOptions> options = traced ? std::nullopt : std::optional(options_from(args));
    const ThreadLimit limit(args.threads);
    SceneOverrides overrides;
    add_scene_settings(args.scene_options, overrides);
    overrides.max_memory_bytes = max_memory_bytes(args.max_memory);
    const std::unique_ptr<LoadedScene> scene = load_scene(args.scene, overrides);
    check_output_paths({{args.output, "--output"}}, scene_inputs(*scene));
    ObjectField chosen = args.object.empty() ? only_implicit_object(*scene->scene, args.scene)
                                             : ObjectField{find_object(*scene->scene, args.object, args.scene), nullptr};
    const SceneObject& object = chosen.object;
    if (traced) {
        const auto* triangles = dynamic_cast<const TriangleMeshShape*>(object.shape.get());
        if (!triangles)
            throw InputError({}, "--object", "object \"" + object.name + "\" is a \"" + object.shape->type_name() +
                                                 "\", which is not traced as triangles");
        // A placement's triangles are in its definition's space; any other object's are baked into the world.
        TriangleMeshData mesh = triangles->data();
        if (object.instanced) mesh.transform(object.to_world);
        write_mesh(args.output, extension, object.name, mesh);
        if (!args.quiet)
            std::printf("%s: traced as triangles: %zu vertices, %zu triangles\nwrote %s\n", printable(object.name).c_str(),
                        mesh.positions.size(), mesh.triangles.size(), args.output.c_str());
        return kExitOk;
    }
    const std::unique_ptr<ImplicitField> field = chosen.field ? std::move(chosen.field) : field_of(object);

    const auto start = std::chrono::steady_clock::now();
    Polygonization result;
    try {
        result = polygonize_field(*field, *options);
    } catch (const std::invalid_argument& error) {
        const std::string message = error.what();
        std::string option = "--object";
        for (const auto& [setting, name] : {std::pair{"origin", "--origin"}, {"depth", "--depth"},
                                            {"simplify", "--simplify"}, {"pole_cap", "--pole-cap"},
                                            {"correct_origin", "--no-origin-correction"}})
            if (message.rfind(std::string(setting) + ":", 0) == 0) option = name;
        throw InputError({}, option, message.substr(message.find(':') == std::string::npos ? 0 : message.find(':') + 2));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (result.mesh.triangles.empty())
        throw InputError({}, "--object", "object \"" + object.name + "\": no surface found at depth " + std::to_string(args.depth));
    const MeshError error = measure_mesh_error(*field, result.mesh, args.error_samples);

    write_mesh(args.output, extension, object.name, result.mesh);
    // Only without origin correction may a mesh have holes (polygonize_field refuses them otherwise): say so, even
    // when quiet.
    if (result.report.edges.boundary || result.report.edges.over_shared)
        std::fprintf(stderr, "warning: the mesh has %zu boundary and %zu over-shared edges (holes where the surface "
                     "passes the uncorrected origin)\n", result.report.edges.boundary, result.report.edges.over_shared);

    if (!args.quiet) {
        const PolygonizeReport& r = result.report;
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        std::printf("%s: %s depth %d: %zu vertices, %zu triangles in %.3f s on %d thread(s) (%zu candidate cells, "
                    "%zu on the surface); peak resident memory of the process %.1f MiB\n",
                    printable(object.name).c_str(), args.method.c_str(), args.depth, result.mesh.positions.size(),
                    result.mesh.triangles.size(), seconds, limit.threads(), r.candidate_cells, r.surface_cells,
                    double(usage.ru_maxrss) / 1024);
        if (options->method == PolygonizeMethod::SphericalDualContouring)
            std::printf("origin (%g, %g, %g) -> (%g, %g, %g) in %d steps%s; r in [%g, %g]; %zu ghost vertices\n",
                        r.requested_origin.x, r.requested_origin.y, r.requested_origin.z, r.range.origin.x,
                        r.range.origin.y, r.range.origin.z, r.origin_steps,
                        options->correct_origin && !r.origin_clear ? " (less than two cells clear of the surface)" : "",
                        r.range.r_min, r.range.r_max, r.dual.ghost_vertices);
        if (options->simplify)
            std::printf("simplified to tolerance %g: %zu octree nodes collapsed (%zu refused by topology, %zu by error)\n",
                        *options->simplify, r.simplification.collapsed_nodes, r.simplification.rejected_by_topology,
                        r.simplification.rejected_by_error);
        if (r.dual.split_vertices)
            std::printf("%zu split vertices (tunnels through ambiguous faces)\n", r.dual.split_vertices);
        std::printf("vertex distance to the surface: mean %.3g, max %.3g; Hausdorff estimate %.3g (mesh->surface %.3g, "
                    "surface->mesh %.3g over %zu surface points)\n",
                    error.vertex_mean, error.vertex_max, error.hausdorff(), error.mesh_to_surface,
                    error.surface_to_mesh, error.surface_samples);
        std::printf("wrote %s\n", args.output.c_str());
    }
    return kExitOk;
}

}  // namespace

CommandRunner add_mesh_options(CLI::App* command) {
    auto args = std::make_shared<MeshArguments>();
    command->footer("Implicit objects: marching cubes, octree or spherical-octree dual contouring. Objects traced as "
                    "triangles (mesh, abm_patch): --method traced writes them as they are traced.");
    command->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
    command->add_option("--object", args->object,
                        "Name of the scene object to mesh (default: the scene's only implicit object)")
        ->type_name("NAME");
    command->add_option("--method", args->method,
                        "mc (marching cubes), dc (octree dual contouring), sdc (spherical) or traced (the triangles "
                        "the renderer traces)")
        ->type_name("mc|dc|sdc|traced")
        ->capture_default_str();
    command->add_option("--depth", args->depth, "Octree depth L: 2^L cells along each axis (sdc: from 2)")
        ->capture_default_str()
        ->check(CLI::Range(1, 10));
    command->add_option("--origin", args->origin, "sdc: origin of the spherical octree (default: centre of the bounds)")
        ->delimiter(',')
        ->expected(3);
    command->add_option("--simplify", args->simplify,
                        "dc: collapse octree cells whose vertex stays within this distance (scene units) of every "
                        "tangent plane of the surface crossings in the cell, where the topology allows (default: none)")
        ->type_name("DISTANCE>=0");
    command->add_flag("--no-origin-correction", args->no_origin_correction,
                      "sdc: keep the origin even when it lies on the surface (for comparison)");
    command->add_option("--pole-cap", args->pole_cap,
                        "sdc: ghost vertex at the poles: axis, normal or vertical (default: axis)")
        ->type_name("axis|normal|vertical");
    command->add_option("--error-samples", args->error_samples, "Sample points for the Hausdorff estimate")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t(1), std::size_t(10000000)));
    command->add_option("-o,--output", args->output, "Mesh file: .ply (binary) or .obj, in world space")
        ->type_name("PATH")
        ->required();
    add_threads_option(*command, args->threads);
    add_max_memory_option(*command, args->max_memory);
    command->add_flag("-q,--quiet", args->quiet, "No summary");
    add_scene_options(*command, args->scene_options);
    return [args] { return run_mesh(*args); };
}

}  // namespace isotrace::cli
