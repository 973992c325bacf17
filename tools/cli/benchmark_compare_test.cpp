#include "tools/cli/benchmark_compare.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "renderer/core/input_error.h"
#include "tools/cli/benchmark_result.h"

namespace isotrace::cli {
namespace {

TEST(BenchmarkCompare, RatioOfRatesWithAnIntervalThatNarrowsWithUnits) {
    const RatioInterval same = rate_ratio({1, 1, 1}, {1, 1, 1});
    EXPECT_DOUBLE_EQ(same.ratio, 1);
    EXPECT_DOUBLE_EQ(same.low, 1);  // no spread: no width
    EXPECT_DOUBLE_EQ(same.high, 1);
    const RatioInterval twice = rate_ratio({2, 2}, {1, 1});
    EXPECT_DOUBLE_EQ(twice.ratio, 2);  // B takes half the time: twice the rate
    const RatioInterval few = rate_ratio({0.9, 1.1}, {0.45, 0.55});
    const RatioInterval many = rate_ratio({0.9, 1.1, 0.9, 1.1, 0.9, 1.1, 0.9, 1.1}, {0.45, 0.55, 0.45, 0.55, 0.45, 0.55, 0.45, 0.55});
    EXPECT_NEAR(few.ratio, 2, 1e-12);
    EXPECT_LT(few.low, few.ratio);
    EXPECT_GT(few.high, few.ratio);
    EXPECT_LT(many.high - many.low, few.high - few.low);
    EXPECT_EQ(rate_ratio({}, {1}).ratio, 0);
}

class BenchmarkResultFileTest : public ::testing::Test {
protected:
    std::string write(const std::string& name, const std::string& text) {
        const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                           ("isotrace_benchmark_compare_" + std::to_string(getpid()) + "_" + name);
        std::ofstream(path) << text;
        paths_.push_back(path);
        return path.string();
    }
    void TearDown() override {
        for (const auto& p : paths_) std::filesystem::remove(p);
    }
    std::vector<std::filesystem::path> paths_;
};

nlohmann::json result_of(double seconds) {
    BenchmarkReferences references;
    for (const BenchmarkWorkload& w : benchmark_workloads()) references.workloads[w.name] = {"h", 1, 2};
    std::vector<BenchmarkWorkloadResult> results;
    for (const BenchmarkWorkload& w : benchmark_workloads())
        results.push_back({&w, {{1, {seconds, seconds * 1.1}, {"h"}}, {2, {seconds / 2, seconds / 2}, {"h"}}}});
    return benchmark_result_json(results, references, false, {});
}

TEST_F(BenchmarkResultFileTest, ComparesTwoResults) {
    const nlohmann::json a = read_benchmark_result(write("a.json", result_of(1).dump()));
    const nlohmann::json b = read_benchmark_result(write("b.json", result_of(0.5).dump()));
    const std::string table = benchmark_comparison(a, b);
    EXPECT_NE(table.find("blobs_1k"), std::string::npos) << table;
    EXPECT_NE(table.find(" 2.000"), std::string::npos) << table;
    EXPECT_NE(table.find("overall, B on 2 thread(s)"), std::string::npos) << table;
}

TEST_F(BenchmarkResultFileTest, RefusesAnotherSuiteAnotherFormatAndOtherFiles) {
    nlohmann::json other = result_of(1);
    other["benchmark"] = "isotrace-bench 0";
    EXPECT_THROW(read_benchmark_result(write("other.json", other.dump())), InputError);
    nlohmann::json format = result_of(1);
    format["result_format"] = 99;
    EXPECT_THROW(read_benchmark_result(write("format.json", format.dump())), InputError);
    EXPECT_THROW(read_benchmark_result(write("text.json", "not json")), InputError);
    EXPECT_THROW(read_benchmark_result(write("bench.json", "{\"isotrace_bench\": 2}")), InputError);
    nlohmann::json broken = result_of(1);
    broken["workloads"][0]["runs"][0]["unit_seconds"] = "fast";
    EXPECT_THROW(read_benchmark_result(write("broken.json", broken.dump())), InputError);
}

}  // namespace
}  // namespace isotrace::cli
