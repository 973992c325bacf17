// isotrace deform: applies sweep deformers (or any registered mesh deformer) to a mesh file offline and writes
// the result as PLY or OBJ, printing binding statistics and the output's quality against the input (flipped
// faces, edge stretch, self-intersections).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "geometry/mesh/mesh_deformer.h"
#include "geometry/mesh/mesh_file.h"
#include "geometry/mesh/mesh_quality.h"
#include "renderer/core/input_error.h"
#include "renderer/core/memory_budget.h"
#include "renderer/core/lower_extension.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/commands.h"
#include "tools/cli/obj_writer.h"
#include "tools/cli/ply_writer.h"
#include "tools/cli/thread_limit.h"
#include "tools/cli/memory_limit_option.h"

namespace isotrace::cli {
namespace {

struct DeformArguments {
    std::string mesh;
    std::string deformers;
    std::string output;
    std::string max_memory;
    int threads = 0;
    bool quiet = false;
};

int run_deform(const DeformArguments& args) {
    const std::string extension = lower_extension(args.output);
    if (extension != ".ply" && extension != ".obj")
        throw InputError({}, "--output", "\"" + args.output + "\" must end in .ply or .obj");
    check_output_paths({{args.output, "--output"}}, {{args.mesh, "the mesh"}, {args.deformers, "the deformer file"}});
    const ThreadLimit limit(args.threads);
    const auto memory = std::make_shared<MemoryBudget>(
        max_memory_bytes(args.max_memory).value_or(MemoryBudget::default_limit_bytes()));
    TriangleMeshData mesh = load_mesh_file(args.mesh, *memory);
    // The quality check (not with --quiet) compares with a copy of the input.
    std::optional<MemoryReservation> quality_memory;
    if (!args.quiet) {
        const std::uint64_t copy = saturating_sum({saturating_product({mesh.positions.size(), sizeof(Vec3f)}),
                                                   saturating_product({mesh.normals.size(), sizeof(Vec3f)}),
                                                   saturating_product({mesh.uvs.size(), sizeof(mesh.uvs[0])}),
                                                   saturating_product({mesh.triangles.size(), sizeof(mesh.triangles[0])})});
        quality_memory.emplace(*memory, saturating_sum({copy, saturating_product({mesh.triangles.size(), kMeshQualityBytesPerTriangle})}),
                               "the input mesh's copy and the quality check of the output");
    }
    const TriangleMeshData input = args.quiet ? TriangleMeshData{} : mesh;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<std::string> summaries = apply_mesh_deformer_file(args.deformers, mesh, memory);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (extension == ".ply") {
        write_ply(args.output, mesh);
    } else {
        write_obj(args.output, {{std::filesystem::path(args.mesh).stem().string(), mesh}});
    }
    if (!args.quiet) {
        for (const std::string& line : summaries) std::fprintf(stderr, "isotrace: %s\n", line.c_str());
        std::fprintf(stderr, "isotrace: mesh quality: %s\n", describe(measure_mesh_quality(input, mesh)).c_str());
        std::fprintf(stderr, "isotrace: deformed %zu vertices in %.3f s on %d thread(s)\nwrote %s\n",
                     mesh.positions.size(), seconds, limit.threads(), args.output.c_str());
    }
    return kExitOk;
}

}  // namespace

CommandRunner add_deform_options(CLI::App* command) {
    auto args = std::make_shared<DeformArguments>();
    command->add_option("mesh", args->mesh, "Mesh file (.obj, .ply or .bpt Bezier patches)")->required()->check(CLI::ExistingFile);
    command->add_option("deformers", args->deformers, "Deformer file (JSON: {\"deformers\": [...]})")
        ->required()
        ->check(CLI::ExistingFile);
    command->add_option("-o,--output", args->output, "Deformed mesh, .ply (binary) or .obj")
        ->type_name("PATH")
        ->required();
    add_threads_option(*command, args->threads);
    add_max_memory_option(*command, args->max_memory);
    command->add_flag("-q,--quiet", args->quiet, "No statistics on stderr");
    return [args] { return run_deform(*args); };
}

}  // namespace isotrace::cli
