#pragma once
// The frozen suite of isotrace benchmark ("isotrace-bench 1"): which scenes it runs, what one unit of work is and
// how many units a timed run holds. The scenes live in scenes/benchmark/isotrace-bench-1 (installed to
// share/isotrace/benchmark), beside references.json: each workload's output hash and the reference machine's rates.
// Changing a scene, a unit or a count makes a new suite version, never a new meaning for an old one.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace isotrace::cli {

inline constexpr const char* kBenchmarkSuite = "isotrace-bench 1";

enum class BenchmarkUnitKind {
    Render,      // one render of the scene as the file sets it (resolution, samples, integrator)
    Polygonise,  // one dual-contouring mesh of one object of the scene
};

struct BenchmarkWorkload {
    std::string name;      // "blobs_10k"
    std::string scene;     // file name in the suite folder
    BenchmarkUnitKind kind;
    std::string object;    // Polygonise: the object meshed
    int depth = 0;         // Polygonise: octree depth
    int units = 1;         // units in one timed run: about 14 s on one core of the reference machine
    std::string measures;  // what the workload stands for, for the help text and the docs
};

// Every workload, in the order they run.
const std::vector<BenchmarkWorkload>& benchmark_workloads();

// Per workload, from references.json: the hash of one unit's output and the reference machine's units per second
// on one thread and on all its threads (0 when not recorded). Embree's kernels for CPUs without AVX2 (SSE2, SSE4.2,
// AVX) decide a few triangle hits at shared edges differently from its AVX2 ones, which use fused multiply-adds: a
// workload whose output they change has its hash for them too (`hash_without_avx2`; empty when it is the same).
struct BenchmarkReference {
    std::string hash;
    double single_thread_rate = 0, all_threads_rate = 0;
    std::string hash_without_avx2{};

    // The reference output's hash where Embree runs its kernels for `embree_isa` (as machine_description names it).
    const std::string& hash_for(std::string_view embree_isa) const;
};
struct BenchmarkReferences {
    std::string machine;  // a description of the reference machine
    std::map<std::string, BenchmarkReference> workloads;
};

// Reads `folder`/references.json; throws InputError when it is missing, malformed, of another suite or lacks a
// workload of the suite.
BenchmarkReferences read_benchmark_references(const std::filesystem::path& folder);

// The suite folder that comes with this executable: <exe>/../share/isotrace/benchmark/isotrace-bench-1 (the build
// tree copies it there, cmake --install installs it there). Empty when it cannot be found.
std::filesystem::path installed_benchmark_folder();

}  // namespace isotrace::cli
