#include "tools/cli/machine_description.h"

#include <gtest/gtest.h>

namespace isotrace::cli {
namespace {

TEST(MachineDescription, HasEveryField) {
    const nlohmann::json machine = machine_description();
    for (const char* key : {"cpu", "cores", "embree_isa", "embree_native_packets", "blob_march_isa", "embree_version",
                            "compiler", "flags", "build_type", "isotrace_version", "commit"})
        EXPECT_TRUE(machine.contains(key)) << key;
    EXPECT_GE(machine["cores"].get<unsigned>(), 1u);
    EXPECT_FALSE(machine["compiler"].get<std::string>().empty());
    EXPECT_EQ(machine["embree_version"].get<std::string>().substr(0, 2), "3.");
    const std::string commit = machine["commit"].get<std::string>();
    // 40 hex digits, "-dirty" after them for a build of uncommitted changes, or "unknown" outside a git checkout.
    const std::string hash = commit.substr(0, commit.find('-'));
    EXPECT_TRUE(commit == "unknown" || (hash.size() == 40 && hash.find_first_not_of("0123456789abcdef") == std::string::npos &&
                                        (commit.size() == 40 || commit.substr(40) == "-dirty")))
        << commit;
}

TEST(MachineDescription, IsaFromCpuFlags) {
    EXPECT_EQ(isa_from_cpu_flags("fpu sse sse2"), "SSE2");
    EXPECT_EQ(isa_from_cpu_flags("sse2 ssse3 sse4_1 sse4_2"), "SSE4.2");
    EXPECT_EQ(isa_from_cpu_flags("sse2 sse4_2 avx"), "AVX");
    EXPECT_EQ(isa_from_cpu_flags("sse2 sse4_2 avx avx2 fma bmi1 bmi2 lzcnt"), "AVX2");
    EXPECT_EQ(isa_from_cpu_flags("sse2 sse4_2 avx avx2 fma bmi1 bmi2 abm"), "AVX2");
    EXPECT_EQ(isa_from_cpu_flags("sse2 avx avx2"), "AVX");  // AVX2 without FMA and BMI: Embree's AVX2 target needs them
    EXPECT_EQ(isa_from_cpu_flags("sse2 avx avx2 fma bmi1 bmi2 abm avx512f avx512dq avx512cd avx512bw avx512vl"),
              "AVX512SKX");
    EXPECT_EQ(isa_from_cpu_flags(""), "unknown");
    EXPECT_EQ(isa_from_cpu_flags("avx2x sse2y"), "unknown");  // whole words only
}

TEST(MachineDescription, EmbreeKernelsBeforeAvx2) {
    for (const char* isa : {"SSE2", "SSE4.2", "AVX"}) EXPECT_TRUE(embree_isa_before_avx2(isa)) << isa;
    for (const char* isa : {"AVX2", "AVX512SKX", "unknown", ""}) EXPECT_FALSE(embree_isa_before_avx2(isa)) << isa;
}

}  // namespace
}  // namespace isotrace::cli
