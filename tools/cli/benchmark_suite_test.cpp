#include "tools/cli/benchmark_suite.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "renderer/core/input_error.h"

namespace isotrace::cli {
namespace {

class BenchmarkReferencesTest : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = std::filesystem::temp_directory_path() /
                  ("isotrace_benchmark_references_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                   "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }

    void write(const std::string& text) { std::ofstream(folder_ / "references.json") << text; }

    // A references.json naming every workload, with `extra` inserted among the workloads.
    std::string complete(const std::string& suite, const std::string& extra = "") {
        std::string text = "{\"suite\": \"" + suite + "\", \"reference_machine\": \"a box\", \"workloads\": {" + extra;
        bool first = extra.empty();
        for (const BenchmarkWorkload& w : benchmark_workloads()) {
            text += std::string(first ? "" : ", ") + "\"" + w.name + "\": {\"hash\": \"h-" + w.name +
                    "\", \"single_thread_units_per_second\": 2, \"all_threads_units_per_second\": 3.5}";
            first = false;
        }
        return text + "}}";
    }

    std::filesystem::path folder_;
};

TEST(BenchmarkSuite, WorkloadsAreNamedOnceAndSized) {
    std::set<std::string> names;
    for (const BenchmarkWorkload& w : benchmark_workloads()) {
        EXPECT_TRUE(names.insert(w.name).second) << w.name;
        EXPECT_GE(w.units, 1) << w.name;
        EXPECT_FALSE(w.measures.empty()) << w.name;
        if (w.kind == BenchmarkUnitKind::Polygonise) EXPECT_FALSE(w.object.empty()) << w.name;
    }
    EXPECT_GE(names.size(), 7u);
}

TEST_F(BenchmarkReferencesTest, ReadsEveryWorkload) {
    write(complete(kBenchmarkSuite));
    const BenchmarkReferences references = read_benchmark_references(folder_);
    EXPECT_EQ(references.machine, "a box");
    ASSERT_EQ(references.workloads.size(), benchmark_workloads().size());
    const BenchmarkReference& blobs = references.workloads.at("blobs_1k");
    EXPECT_EQ(blobs.hash, "h-blobs_1k");
    EXPECT_EQ(blobs.single_thread_rate, 2);
    EXPECT_EQ(blobs.all_threads_rate, 3.5);
    EXPECT_EQ(blobs.hash_without_avx2, "");
}

// Embree's kernels for CPUs without AVX2 decide a few triangle hits differently: a workload may name their output's
// hash too, which applies where Embree runs them and only there.
TEST_F(BenchmarkReferencesTest, AWorkloadMayNameItsHashWithoutAvx2) {
    const std::string& name = benchmark_workloads().front().name;
    std::string text = complete(kBenchmarkSuite);
    const std::string entry = "\"" + name + "\": {\"hash\": \"h-" + name + "\"";
    text.replace(text.find(entry), entry.size(), entry + ", \"hash_without_avx2\": \"old-" + name + "\"");
    write(text);
    const BenchmarkReferences references = read_benchmark_references(folder_);
    const BenchmarkReference& first = references.workloads.at(name);
    for (const char* isa : {"SSE2", "SSE4.2", "AVX"}) EXPECT_EQ(first.hash_for(isa), "old-" + name) << isa;
    for (const char* isa : {"AVX2", "AVX512SKX", "unknown", ""}) EXPECT_EQ(first.hash_for(isa), "h-" + name) << isa;
    // A workload without one has the same hash everywhere.
    const BenchmarkReference& last = references.workloads.at(benchmark_workloads().back().name);
    EXPECT_EQ(last.hash_for("AVX"), last.hash);
}

TEST_F(BenchmarkReferencesTest, RefusesAnotherSuiteAMissingOrUnknownWorkloadAndNoFile) {
    EXPECT_THROW(read_benchmark_references(folder_), InputError);  // no file yet
    write(complete("isotrace-bench 0"));
    EXPECT_THROW(read_benchmark_references(folder_), InputError);
    write(complete(kBenchmarkSuite, "\"not_a_workload\": {\"hash\": \"x\"}"));
    EXPECT_THROW(read_benchmark_references(folder_), InputError);
    write("{\"suite\": \"isotrace-bench 1\", \"workloads\": {}}");
    try {
        read_benchmark_references(folder_);
        FAIL() << "a missing workload was accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find(benchmark_workloads().front().name), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace isotrace::cli
