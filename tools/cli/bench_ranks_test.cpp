// The aggregate of isotrace bench over MPI ranks: per workload and thread count, each rank's median and their sum.
#include "tools/cli/bench_ranks.h"

#include <gtest/gtest.h>

namespace isotrace::cli {
namespace {

nlohmann::json workloads(double primary_1, double primary_2, double path_1) {
    const auto run = [](int threads, double median) {
        return nlohmann::json{{"threads", threads}, {"throughput", {{"median", median}}}};
    };
    return nlohmann::json::array(
        {{{"name", "cornell_box/primary"}, {"unit", "Mrays/s"}, {"runs", {run(1, primary_1), run(2, primary_2)}}},
         {{"name", "cornell_box/path"}, {"unit", "Msamples/s"}, {"runs", {run(1, path_1)}}}});
}

TEST(BenchRanks, SumsEachRanksMedianPerWorkloadAndThreadCount) {
    const nlohmann::json aggregate = rank_aggregate({workloads(10, 18, 1), workloads(8, 15, 0.5)});
    EXPECT_EQ(aggregate["ranks"], 2);
    const auto& primary = aggregate["workloads"][0];
    EXPECT_EQ(primary["name"], "cornell_box/primary");
    EXPECT_DOUBLE_EQ(primary["runs"][0]["total"].get<double>(), 18.0);
    EXPECT_DOUBLE_EQ(primary["runs"][1]["total"].get<double>(), 33.0);
    EXPECT_DOUBLE_EQ(primary["runs"][1]["per_rank"][1].get<double>(), 15.0);
    EXPECT_DOUBLE_EQ(aggregate["workloads"][1]["runs"][0]["total"].get<double>(), 1.5);
    const std::string table = rank_aggregate_table(aggregate);
    EXPECT_NE(table.find("Aggregate of 2 ranks"), std::string::npos);
    EXPECT_NE(table.find("cornell_box/path"), std::string::npos);
}

TEST(BenchRanks, ARankWithoutAWorkloadIsAnError) {
    nlohmann::json short_of_one = workloads(1, 2, 3);
    short_of_one.erase(1);
    EXPECT_THROW(rank_aggregate({workloads(1, 2, 3), short_of_one}), std::runtime_error);
}

}  // namespace
}  // namespace isotrace::cli
