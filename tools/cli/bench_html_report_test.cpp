#include "tools/cli/bench_html_report.h"

#include <gtest/gtest.h>

#include "tools/cli/well_formed_markup_test.h"

namespace isotrace::cli {
namespace {

nlohmann::json example_report(bool two_thread_counts, bool scaling) {
    nlohmann::json runs = {{{"threads", 1},
                            {"seconds", {0.5}},
                            {"throughput", {{"median", 12.5}, {"min", 12}, {"q1", 12.25}, {"q3", 12.75}, {"max", 13}}},
                            {"speedup", 1},
                            {"efficiency", 1}}};
    if (two_thread_counts)
        runs.push_back({{"threads", 2},
                        {"seconds", {0.3}},
                        {"throughput", {{"median", 23.75}, {"min", 23}, {"q1", 23.5}, {"q3", 24}, {"max", 24.5}}},
                        {"speedup", 1.9},
                        {"efficiency", 0.95}});
    nlohmann::json report = {
        {"machine",
         {{"cpu", "Example CPU @ 3 GHz"},
          {"cores", 2},
          {"embree_isa", "AVX2"},
          {"compiler", "GNU 12.2.0"},
          {"flags", "-O3 -DNDEBUG"},
          {"isotrace_version", "0.1.0"},
          {"commit", "0123456789abcdef0123456789abcdef01234567"}}},
        {"settings", {{"threads", two_thread_counts ? nlohmann::json{1, 2} : nlohmann::json{1}}, {"repeats", 1}, {"quick", true}}},
        {"workloads",
         {{{"name", "blobs_1k/primary"}, {"unit", "Mrays/s"}, {"build_seconds", 0.01}, {"peak_memory_bytes", 1 << 20},
           {"runs", runs}},
          {{"name", "metacube_dog/path"}, {"unit", "Msamples/s"}, {"build_seconds", 0.5}, {"peak_memory_bytes", 1 << 24},
           {"runs", runs}}}},
        {"scaling", nullptr},
        {"blob_comparison", nullptr}};
    if (scaling)
        report["scaling"] = {{"threads", 2},
                             {"points",
                              {{{"elements", 1000}, {"rays", 100}, {"build_seconds", 0.001}, {"ns_per_ray", 480}, {"cost_growth", 1},
                                {"bytes_per_element", 812}},
                               {{"elements", 10000}, {"rays", 100}, {"build_seconds", 0.01}, {"ns_per_ray", 650},
                                {"cost_growth", 1.354}, {"bytes_per_element", 790}}}}};
    return report;
}

TEST(BenchHtmlReport, SelfContainedWellFormedPage) {
    const std::string html = bench_html_report(example_report(true, true));
    EXPECT_TRUE(well_formed_markup(html));
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(html.find("http://"), html.find("http://www.w3.org/2000/svg"));  // only the SVG namespace
    EXPECT_EQ(html.find("https://"), std::string::npos);
}

TEST(BenchHtmlReport, ShowsTheMachineAndTheNumbers) {
    const std::string html = bench_html_report(example_report(true, true));
    for (const char* text : {"Example CPU @ 3 GHz", "AVX2", "GNU 12.2.0", "0123456789abcdef0123456789abcdef01234567",
                             "blobs_1k/primary", "metacube_dog/path", ">23.75<", ">12.5<", ">1.9<", "95 %",
                             "Thread scaling", "ideal", "Time per primary ray", "Memory per element", ">650<", ">812<", ">1.354<"})
        EXPECT_NE(html.find(text), std::string::npos) << text;
    // A bar chart per unit.
    EXPECT_NE(html.find("Mrays/s on 2 thread(s)"), std::string::npos);
    EXPECT_NE(html.find("Msamples/s on 2 thread(s)"), std::string::npos);
}

TEST(BenchHtmlReport, SaysWhatWasNotMeasured) {
    const std::string html = bench_html_report(example_report(false, false));
    EXPECT_TRUE(well_formed_markup(html));
    EXPECT_NE(html.find("--threads 1,2"), std::string::npos);
    EXPECT_NE(html.find("--scaling"), std::string::npos);
    EXPECT_EQ(html.find("stroke-dasharray"), std::string::npos);  // no scaling plot, so no ideal line
}

}  // namespace
}  // namespace isotrace::cli
