#include "tools/cli/benchmark_result.h"

#include <gtest/gtest.h>

namespace isotrace::cli {
namespace {

// Every workload with a reference rate of 1 unit/s on one thread and 2 on all, and hash "h".
BenchmarkReferences references() {
    BenchmarkReferences r;
    r.machine = "reference";
    for (const BenchmarkWorkload& w : benchmark_workloads()) r.workloads[w.name] = {"h", 1, 2};
    return r;
}

// Every workload run on 1 and 2 threads, each unit taking `seconds` (2 threads: half), giving `hash`.
std::vector<BenchmarkWorkloadResult> results(double seconds, const std::string& hash) {
    std::vector<BenchmarkWorkloadResult> all;
    for (const BenchmarkWorkload& w : benchmark_workloads())
        all.push_back({&w, {{1, {seconds, seconds}, {hash}}, {2, {seconds / 2, seconds / 2}, {hash}}}});
    return all;
}

TEST(BenchmarkResult, ReadableSystemFacts) {
    const nlohmann::json caches = nlohmann::json::parse(
        R"([{"level": 1, "type": "data", "bytes": 32768, "count": 2}, {"level": 3, "type": "unified", "bytes": 33554432, "count": 1}])");
    EXPECT_EQ(readable_system_fact("caches", caches), "L1 data 32 KiB x2, L3 unified 32 MiB x1");
    EXPECT_EQ(readable_system_fact("clock_mhz", {{"base", nullptr}, {"current", 2445.4}}), "current 2445 MHz");
    EXPECT_EQ(readable_system_fact("clock_mhz", {{"base", nullptr}}), "unknown");
    EXPECT_EQ(readable_system_fact("memory_bytes", std::uint64_t(24) << 30), "24.0 GiB");
    EXPECT_EQ(readable_system_fact("smt", false), "no");
    EXPECT_EQ(readable_system_fact("os", "Debian"), "Debian");
    EXPECT_EQ(readable_system_fact("memory_speed", nullptr), "unknown");
}

TEST(BenchmarkResult, GeometricMean) {
    EXPECT_DOUBLE_EQ(geometric_mean({4, 9}), 6);
    EXPECT_DOUBLE_EQ(geometric_mean({1000}), 1000);
    EXPECT_EQ(geometric_mean({}), 0);
}

TEST(BenchmarkResult, TheReferenceMachineScores1000) {
    const nlohmann::json result = benchmark_result_json(results(1, "h"), references(), false, {});
    EXPECT_TRUE(result["valid"].get<bool>());
    EXPECT_EQ(result["benchmark"], kBenchmarkSuite);
    EXPECT_EQ(result["threads"], nlohmann::json::array({1, 2}));
    ASSERT_EQ(result["scores"].size(), 2u);
    EXPECT_NEAR(result["scores"][0]["score"].get<double>(), 1000, 1e-9);
    EXPECT_NEAR(result["scores"][1]["score"].get<double>(), 1000, 1e-9);  // the reference's 2 units/s on 2 threads
    const std::string summary = benchmark_summary(result);
    EXPECT_NE(summary.find("Score (1 thread): 1000"), std::string::npos) << summary;
    EXPECT_NE(summary.find("Score (2 threads): 1000"), std::string::npos) << summary;
    // Twice as fast on one thread: twice the score.
    EXPECT_NEAR(benchmark_result_json(results(0.5, "h"), references(), false, {})["scores"][0]["score"].get<double>(),
                2000, 1e-9);
}

TEST(BenchmarkResult, SpreadIsTheSlowestAndFastestUnit) {
    std::vector<BenchmarkWorkloadResult> all = results(1, "h");
    all[0].runs[0].seconds = {0.5, 1, 2};
    const nlohmann::json run = benchmark_result_json(all, references(), false, {})["workloads"][0]["runs"][0];
    EXPECT_DOUBLE_EQ(run["units_per_second"].get<double>(), 3 / 3.5);
    EXPECT_DOUBLE_EQ(run["units_per_second_min"].get<double>(), 0.5);
    EXPECT_DOUBLE_EQ(run["units_per_second_max"].get<double>(), 2);
    EXPECT_DOUBLE_EQ(run["score_max"].get<double>(), 2000);
}

TEST(BenchmarkResult, AWrongOutputVoidsTheScore) {
    std::vector<BenchmarkWorkloadResult> all = results(1, "h");
    all[2].runs[1].hashes = {"tampered"};
    const nlohmann::json result = benchmark_result_json(all, references(), false, {});
    EXPECT_FALSE(result["valid"].get<bool>());
    EXPECT_FALSE(result["workloads"][2]["valid"].get<bool>());
    EXPECT_TRUE(result["workloads"][0]["valid"].get<bool>());
    EXPECT_TRUE(result["scores"][0]["score"].is_null());
    EXPECT_TRUE(result["workloads"][0]["runs"][0]["score"].is_number());
    EXPECT_TRUE(result["workloads"][2]["runs"][0]["score"].is_null());
    ASSERT_EQ(result["problems"].size(), 1u);
    const std::string summary = benchmark_summary(result);
    EXPECT_NE(summary.find("SCORE VOID"), std::string::npos) << summary;
    EXPECT_NE(summary.find(benchmark_workloads()[2].name), std::string::npos) << summary;
}

// The output is checked against the hash for the Embree kernels the machine runs (the system's "embree_isa").
TEST(BenchmarkResult, TheReferenceHashIsTheOneForTheMachinesEmbreeKernels) {
    BenchmarkReferences older = references();
    older.workloads.at(benchmark_workloads()[1].name).hash_without_avx2 = "h-sse";
    std::vector<BenchmarkWorkloadResult> all = results(1, "h");
    for (BenchmarkRun& run : all[1].runs) run.hashes = {"h-sse"};
    const nlohmann::json on_avx = benchmark_result_json(all, older, false, {{"embree_isa", "AVX"}});
    EXPECT_TRUE(on_avx["valid"].get<bool>()) << on_avx["problems"].dump();
    EXPECT_EQ(on_avx["workloads"][1]["reference_hash"], "h-sse");
    EXPECT_EQ(on_avx["workloads"][0]["reference_hash"], "h");
    // The same output where Embree runs its AVX2 kernels is wrong, and so is the AVX2 output on AVX.
    const nlohmann::json on_avx2 = benchmark_result_json(all, older, false, {{"embree_isa", "AVX2"}});
    EXPECT_FALSE(on_avx2["valid"].get<bool>());
    EXPECT_FALSE(on_avx2["workloads"][1]["valid"].get<bool>());
    EXPECT_FALSE(benchmark_result_json(results(1, "h"), older, false, {{"embree_isa", "SSE4.2"}})["valid"].get<bool>());
}

TEST(BenchmarkResult, OneThreadCountHasNoSpeedUpAndAPartialSuiteNoOverallScore) {
    std::vector<BenchmarkWorkloadResult> all = results(1, "h");
    for (BenchmarkWorkloadResult& r : all) r.runs.pop_back();
    all.pop_back();
    const nlohmann::json result = benchmark_result_json(all, references(), true, {});
    EXPECT_EQ(result["threads"], nlohmann::json::array({1}));
    EXPECT_EQ(result["mode"], "short");
    EXPECT_TRUE(result["valid"].get<bool>());
    EXPECT_TRUE(result["scores"][0]["score"].is_null());
    EXPECT_TRUE(result["workloads"][0]["runs"][0]["score"].is_null());  // short: no per-workload score either
    EXPECT_TRUE(benchmark_result_json(all, references(), false, {})["workloads"][0]["runs"][0]["score"].is_number());
    const std::string summary = benchmark_summary(result);
    EXPECT_EQ(summary.find("speed-up"), std::string::npos) << summary;
    EXPECT_NE(summary.find("not scores to quote"), std::string::npos) << summary;
    EXPECT_NE(summary.find("No scores: a short run"), std::string::npos) << summary;
}

}  // namespace
}  // namespace isotrace::cli
