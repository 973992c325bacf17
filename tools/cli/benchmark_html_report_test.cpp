#include "tools/cli/benchmark_html_report.h"

#include <gtest/gtest.h>

#include "tools/cli/benchmark_result.h"
#include "tools/cli/well_formed_markup_test.h"

namespace isotrace::cli {
namespace {

nlohmann::json result(const std::string& hash, int thread_counts) {
    BenchmarkReferences references;
    references.machine = "the <reference> box";
    for (const BenchmarkWorkload& w : benchmark_workloads()) references.workloads[w.name] = {"h", 1, 2};
    std::vector<BenchmarkWorkloadResult> results;
    for (const BenchmarkWorkload& w : benchmark_workloads()) {
        BenchmarkWorkloadResult r{&w, {{1, {1, 1.5}, {hash}}}};
        if (thread_counts == 2) r.runs.push_back({2, {0.5, 0.6}, {hash}});
        results.push_back(r);
    }
    return benchmark_result_json(
        results, references, false,
        {{"cpu", "Test CPU"}, {"caches", {{{"level", 2}, {"type", "unified"}, {"bytes", 524288}, {"count", 2}}}}});
}

TEST(BenchmarkHtmlReport, ScoresSpeedUpAndSystem) {
    const std::string html = benchmark_html_report(result("h", 2));
    EXPECT_NE(html.find("Score on 1 thread"), std::string::npos);
    EXPECT_NE(html.find("Score on 2 threads"), std::string::npos);
    EXPECT_NE(html.find("Speed-up of 2 threads over 1 thread"), std::string::npos);
    EXPECT_NE(html.find("Test CPU"), std::string::npos);
    EXPECT_NE(html.find("L2 unified 512 KiB x2"), std::string::npos);
    EXPECT_NE(html.find("the &lt;reference&gt; box"), std::string::npos);
    EXPECT_EQ(html.find("Score void"), std::string::npos);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_TRUE(well_formed_markup(html));
}

TEST(BenchmarkHtmlReport, VoidAndOneThreadCount) {
    const std::string html = benchmark_html_report(result("tampered", 1));
    EXPECT_NE(html.find("Score void"), std::string::npos);
    EXPECT_NE(html.find("Units per second on 1 thread"), std::string::npos);  // no scores to chart
    EXPECT_NE(html.find("no speed-up to show"), std::string::npos);
    EXPECT_EQ(html.find("Speed-up of"), std::string::npos);
    EXPECT_TRUE(well_formed_markup(html));
}

}  // namespace
}  // namespace isotrace::cli
