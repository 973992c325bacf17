// isotrace polygonize: the blob groups of a scene tessellated into a triangle mesh file (Wavefront OBJ).
#include <chrono>
#include <cstdio>

#include "geometry/implicit/blob_group_shape.h"
#include "renderer/core/input_error.h"
#include "renderer/scene/loaded_scene.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/commands.h"
#include "tools/cli/obj_writer.h"
#include "tools/cli/tessellation_options.h"

namespace isotrace::cli {
namespace {

struct PolygonizeArguments {
    std::string scene;
    std::string output;
    TessellationOptions tessellation;
    bool quiet = false;
};

// World space: a group that could not be baked into the world (an instanced object) is moved there here.
void to_world(TriangleMeshData& mesh, const SceneObject& object) {
    if (!object.instanced) return;
    for (Vec3f& p : mesh.positions) p = Vec3f(object.to_world.point(Vec3d(p)));
    for (Vec3f& n : mesh.normals) n = normalize(object.to_world.normal(n));
}

int run_polygonize(const PolygonizeArguments& args) {
    check_output_file(args.output, ".obj", "--output");
    const std::unique_ptr<LoadedScene> scene = load_scene(args.scene);
    std::vector<NamedMesh> meshes;
    for (const SceneObject& object : scene->scene->objects()) {
        const auto* blobs = dynamic_cast<const BlobGroupShape*>(object.shape.get());
        if (!blobs) continue;
        const double cell = args.tessellation.cell_size_for(blobs->group());
        const auto start = std::chrono::steady_clock::now();
        NamedMesh named{object.name, tessellate(blobs->group(), cell, "object \"" + object.name + "\"")};
        to_world(named.mesh, object);
        if (!args.quiet)
            std::fprintf(stderr, "isotrace: %s: %zu elements, cell %g: %zu triangles, %zu vertices in %.2f s\n",
                         object.name.c_str(), blobs->group().elements().size(), cell, named.mesh.triangles.size(),
                         named.mesh.positions.size(),
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        meshes.push_back(std::move(named));
    }
    if (meshes.empty()) throw InputError({}, args.scene, "the scene has no blob group to polygonize");
    write_obj(args.output, meshes);
    if (!args.quiet) std::fprintf(stderr, "wrote %s\n", args.output.c_str());
    return kExitOk;
}

}  // namespace

CommandRunner add_polygonize_command(CLI::App& app) {
    auto args = std::make_shared<PolygonizeArguments>();
    CLI::App* command =
        app.add_subcommand("polygonize", "Tessellate the scene's blob groups into a closed triangle mesh (OBJ)");
    command->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
    command->add_option("-o,--output", args->output, "Mesh file, Wavefront OBJ in world space")->required();
    args->tessellation.add_to(*command);
    command->add_flag("-q,--quiet", args->quiet, "No summary on stderr");
    return [args] { return run_polygonize(*args); };
}

}  // namespace isotrace::cli
