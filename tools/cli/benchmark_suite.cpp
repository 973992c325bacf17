#include "tools/cli/benchmark_suite.h"

#include <system_error>

#include "renderer/core/input_error.h"
#include "renderer/params/json_document.h"
#include "renderer/params/scene_node.h"
#include "tools/cli/machine_description.h"

namespace isotrace::cli {

const std::vector<BenchmarkWorkload>& benchmark_workloads() {
    using K = BenchmarkUnitKind;
    // Units: renders at the resolution and samples per pixel the frozen scene files set, or one mesh, each 0.25 to
    // 0.4 s on one core of the reference machine; `units` makes a timed run last about 14 s there on one thread.
    static const std::vector<BenchmarkWorkload> workloads = {
        {"blobs_1k", "blobs_1k.json", K::Render, "", 0, 44,
         "a group of 1000 blobs, first hits and normals (AOV integrator): the blob field's cell queries"},
        {"blobs_10k", "blobs_10k.json", K::Render, "", 0, 44, "the same at 10 000 blobs: deeper BVH, more overlap"},
        {"blobs_100k", "blobs_100k.json", K::Render, "", 0, 40,
         "the same at 100 000 blobs: memory-bound traversal"},
        {"metacube_dog", "metacube_dog.json", K::Render, "", 0, 35,
         "blended metacubes under a sky, path traced: root finding in a soft field, shading, shadows"},
        {"superquadric_deform", "superquadric_deform.json", K::Render, "", 0, 56,
         "superquadrics twisted, tapered and bent, path traced: deformed implicit surfaces"},
        {"csg_cup", "csg_cup.json", K::Render, "", 0, 45, "a CSG cup (unions, differences, intersections), path traced"},
        {"showcase", "showcase.json", K::Render, "", 0, 44,
         "the showcase still, small: every kind of shape, glass, depth of field, the full path tracer"},
        {"dog_mesh", "metacube_dog.json", K::Polygonise, "dog", 7, 80,
         "the dog polygonised by dual contouring at octree depth 7: field sampling and the QEF solves"},
    };
    return workloads;
}

BenchmarkReferences read_benchmark_references(const std::filesystem::path& folder) {
    const std::string path = (folder / "references.json").string();
    std::error_code ignored;
    if (!std::filesystem::is_regular_file(path, ignored))
        throw InputError({path, 0, 0}, "", "the benchmark suite has no references.json here");
    const JsonValue document = parse_json_file(path);
    auto context = std::make_shared<SceneFileContext>();
    context->file = path;
    context->directory = folder;
    const SceneNode root(document, "", context);
    const std::string suite = root.string("suite");
    if (suite != kBenchmarkSuite)
        root.optional_value("suite")->fail("references of \"" + suite + "\", not of \"" + kBenchmarkSuite + "\"");
    BenchmarkReferences references;
    references.machine = root.string_or("reference_machine", "");
    const SceneNode workloads = root.object("workloads");
    for (const BenchmarkWorkload& workload : benchmark_workloads()) {
        if (!workloads.has(workload.name)) workloads.fail("no reference for the workload \"" + workload.name + "\"");
        const SceneNode entry = workloads.object(workload.name);
        BenchmarkReference& reference = references.workloads[workload.name];
        reference.hash = entry.string("hash");
        reference.hash_without_avx2 = entry.string_or("hash_without_avx2", "");
        reference.single_thread_rate = entry.number_or("single_thread_units_per_second", 0, NumberRange::non_negative());
        reference.all_threads_rate = entry.number_or("all_threads_units_per_second", 0, NumberRange::non_negative());
        entry.finish();
    }
    workloads.finish();
    root.finish();
    return references;
}

const std::string& BenchmarkReference::hash_for(std::string_view embree_isa) const {
    return embree_isa_before_avx2(embree_isa) && !hash_without_avx2.empty() ? hash_without_avx2 : hash;
}

std::filesystem::path installed_benchmark_folder() {
    std::error_code error;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) return {};
    const std::filesystem::path folder =
        (executable.parent_path() / ".." / "share" / "isotrace" / "benchmark" / "isotrace-bench-1").lexically_normal();
    return std::filesystem::is_directory(folder, error) ? folder : std::filesystem::path();
}

}  // namespace isotrace::cli
