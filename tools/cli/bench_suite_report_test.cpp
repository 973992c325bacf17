#include "tools/cli/bench_suite_report.h"

#include <gtest/gtest.h>

namespace isotrace::cli {
namespace {

// Two thread counts of a workload whose runs take known times.
WorkloadResult two_thread_counts() {
    WorkloadResult result;
    result.workload = {"cornell_box/primary", "scenes/cornell_box.json", WorkloadKind::PrimaryRays};
    result.unit = "Mrays/s";
    result.work_per_run = 2e6;  // rays per run
    result.build_seconds = 0.25;
    result.peak_memory_bytes = 64u << 20;
    RayCastTiming one, two;
    one.threads = 1;
    one.seconds = {2.0, 1.0, 4.0};  // 1, 2 and 0.5 Mrays/s: median 1
    two.threads = 2;
    two.seconds = {0.8, 0.5, 1.0};  // 2.5, 4 and 2 Mrays/s: median 2.5
    result.timings = {one, two};
    return result;
}

TEST(BenchSuiteReport, WorkloadJsonHasTheFiguresOfEachThreadCount) {
    const nlohmann::json w = workload_json(two_thread_counts());
    for (const char* key : {"name", "scene", "kind", "unit", "work_per_run", "build_seconds", "scene_bytes",
                            "peak_memory_bytes", "runs"})
        EXPECT_TRUE(w.contains(key)) << key;
    EXPECT_EQ(w["kind"], "primary");
    ASSERT_EQ(w["runs"].size(), 2u);
    const auto& base = w["runs"][0];
    EXPECT_DOUBLE_EQ(base["throughput"]["median"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(base["throughput"]["min"].get<double>(), 0.5);
    EXPECT_DOUBLE_EQ(base["throughput"]["max"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(base["speedup"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(base["efficiency"].get<double>(), 1.0);
    const auto& two = w["runs"][1];
    EXPECT_DOUBLE_EQ(two["throughput"]["median"].get<double>(), 2.5);
    EXPECT_DOUBLE_EQ(two["speedup"].get<double>(), 2.5);
    EXPECT_DOUBLE_EQ(two["efficiency"].get<double>(), 1.25);
    EXPECT_EQ(two["seconds"].size(), 3u);
}

TEST(BenchSuiteReport, ScalingJsonAndTable) {
    const nlohmann::json points = scaling_json({{1000, 100, 0.01, 800, 50, 1}, {10000, 100, 0.1, 700, 75, 1.5}});
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[1]["elements"], 10000);
    EXPECT_DOUBLE_EQ(points[1]["cost_growth"].get<double>(), 1.5);
    const nlohmann::json report = {
        {"machine", {{"cpu", "Test CPU"}, {"cores", 2}, {"embree_isa", "AVX2"}}},
        {"settings", {{"threads", {1, 2}}, {"repeats", 3}}},
        {"workloads", {workload_json(two_thread_counts())}},
        {"scaling", {{"threads", 2}, {"points", points}}}};
    const std::string table = suite_table(report);
    for (const char* text : {"Test CPU", "AVX2", "cornell_box/primary", "Mrays/s", "Thread scaling", "2.50x",
                             "125%", "Element-count scaling", "10000", "1.50x"})
        EXPECT_NE(table.find(text), std::string::npos) << text << "\n" << table;
}

TEST(BenchWorkloads, FilterSelectsByName) {
    const std::vector<Workload> all = suite_workloads();
    const auto names = [](const std::vector<Workload>& list) {
        std::vector<std::string> n;
        for (const Workload& w : list) n.push_back(w.name);
        return n;
    };
    EXPECT_EQ(names(workloads_matching(all, std::regex("^cornell_box/"))),
              (std::vector<std::string>{"cornell_box/primary", "cornell_box/shadow", "cornell_box/bounce",
                                        "cornell_box/path"}));
    const std::vector<Workload> blobs = workloads_matching(all, std::regex("blob"));
    EXPECT_EQ(blobs.size(), 13u);  // three ray kinds on three scenes, three polygonisers on one, and the comparison
    EXPECT_EQ(names(workloads_matching(all, std::regex("/mesh_"))),
              (std::vector<std::string>{"blobs_10k/mesh_mc", "blobs_10k/mesh_dc", "blobs_10k/mesh_sdc",
                                        "metacube_dog/mesh_mc", "metacube_dog/mesh_dc", "metacube_dog/mesh_sdc"}));
    EXPECT_EQ(blobs.back().kind, WorkloadKind::BlobComparison);
    EXPECT_TRUE(workloads_matching(all, std::regex("no such workload")).empty());
    EXPECT_EQ(workloads_matching(all, std::regex(".")).size(), all.size());
    for (const Workload& w : all) {  // every name is "<scene>/<kind>" and names are unique
        EXPECT_EQ(w.name.substr(w.name.find('/') + 1), kind_name(w.kind));
        EXPECT_EQ(workloads_matching(all, std::regex("^" + w.name + "$")).size(), 1u) << w.name;
    }
}

}  // namespace
}  // namespace isotrace::cli
