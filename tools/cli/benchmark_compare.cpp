#include "tools/cli/benchmark_compare.h"

#include <cmath>
#include <cstdio>

#include "renderer/core/input_error.h"
#include "renderer/core/input_file.h"
#include "tools/cli/benchmark_result.h"
#include "tools/cli/benchmark_suite.h"

namespace isotrace::cli {
namespace {

// A result is a few hundred kilobytes at most.
constexpr std::uint64_t kMaxResultBytes = std::uint64_t(16) << 20;

// 1.96: the 97.5 % quantile of the standard normal distribution, for a two-sided 95 % interval.
constexpr double kZ95 = 1.959963984540054;

struct RateMoments {
    double mean = 0, variance_of_mean_relative = 0;  // (sd / mean)^2 / n
};

RateMoments moments(const std::vector<double>& seconds) {
    std::vector<double> rates;
    for (double s : seconds)
        if (s > 0) rates.push_back(1 / s);
    RateMoments m;
    if (rates.empty()) return m;
    for (double r : rates) m.mean += r;
    m.mean /= double(rates.size());
    if (rates.size() < 2) return m;
    double sum = 0;
    for (double r : rates) sum += (r - m.mean) * (r - m.mean);
    const double variance = sum / double(rates.size() - 1);
    m.variance_of_mean_relative = variance / (m.mean * m.mean) / double(rates.size());
    return m;
}

std::vector<double> unit_seconds(const nlohmann::json& run) {
    std::vector<double> seconds;
    for (const auto& s : run["unit_seconds"]) seconds.push_back(s.get<double>());
    return seconds;
}

std::string interval_text(const RatioInterval& r) {
    char text[64];
    std::snprintf(text, sizeof text, "%6.3f  [%.3f, %.3f]", r.ratio, r.low, r.high);
    return text;
}

}  // namespace

nlohmann::json read_benchmark_result(const std::string& path) {
    nlohmann::json result;
    try {
        result = nlohmann::json::parse(read_input_file(path, kMaxResultBytes, "for benchmark results"));
    } catch (const nlohmann::json::exception& error) {
        throw InputError({path, 0, 0}, "", std::string("not a benchmark result: ") + error.what());
    }
    const auto is = [&result](const char* key, auto check) { return result.contains(key) && check(result[key]); };
    if (!result.is_object() || !is("benchmark", [](const auto& v) { return v.is_string(); }) ||
        !is("result_format", [](const auto& v) { return v.is_number_integer(); }) ||
        !is("workloads", [](const auto& v) { return v.is_array(); }))
        throw InputError({path, 0, 0}, "", "not a result of isotrace benchmark --json");
    if (result["benchmark"] != kBenchmarkSuite)
        throw InputError({path, 0, 0}, "benchmark",
                         "a result of \"" + result["benchmark"].get<std::string>() + "\": this isotrace compares results of \"" +
                             kBenchmarkSuite + "\" only (another suite measures other work)");
    if (result["result_format"] != kBenchmarkResultFormat)
        throw InputError({path, 0, 0}, "result_format",
                         "result format " + result["result_format"].dump() + ", this isotrace reads format " +
                             std::to_string(kBenchmarkResultFormat));
    for (const auto& w : result["workloads"]) {
        if (!w.is_object() || !w.contains("name") || !w["name"].is_string() || !w.contains("runs") || !w["runs"].is_array())
            throw InputError({path, 0, 0}, "workloads", "a workload without a name or runs");
        for (const auto& run : w["runs"])
            if (!run.is_object() || !run.contains("threads") || !run["threads"].is_number_integer() ||
                !run.contains("unit_seconds") || !run["unit_seconds"].is_array())
                throw InputError({path, 0, 0}, "workloads", "a run of " + w["name"].get<std::string>() +
                                                                " without its threads or unit_seconds");
            else
                for (const auto& s : run["unit_seconds"])
                    if (!s.is_number())
                        throw InputError({path, 0, 0}, "workloads", "unit_seconds of " + w["name"].get<std::string>() +
                                                                        " holds something that is not a number");
    }
    return result;
}

RatioInterval rate_ratio(const std::vector<double>& a_seconds, const std::vector<double>& b_seconds) {
    const RateMoments a = moments(a_seconds), b = moments(b_seconds);
    if (a.mean <= 0 || b.mean <= 0) return {};
    const double ratio = b.mean / a.mean;
    const double half_width = kZ95 * std::sqrt(a.variance_of_mean_relative + b.variance_of_mean_relative);
    return {ratio, ratio * std::exp(-half_width), ratio * std::exp(half_width)};
}

std::string benchmark_comparison(const nlohmann::json& a, const nlohmann::json& b) {
    std::string text = "B / A in units per second (95 % confidence interval); above 1: B is faster\n";
    if (!a["valid"].get<bool>() || !b["valid"].get<bool>())
        text += "warning: a result is void (an output differed from the reference): its work is not the suite's\n";
    char line[256];
    std::vector<std::pair<int, std::vector<double>>> by_position;  // per thread-count position: the ratios
    for (const auto& wa : a["workloads"])
        for (const auto& wb : b["workloads"]) {
            if (wa["name"] != wb["name"]) continue;
            for (std::size_t i = 0; i < wa["runs"].size() && i < wb["runs"].size(); ++i) {
                const auto& ra = wa["runs"][i];
                const auto& rb = wb["runs"][i];
                const RatioInterval r = rate_ratio(unit_seconds(ra), unit_seconds(rb));
                const std::string threads =
                    ra["threads"] == rb["threads"] ? ra["threads"].dump() : ra["threads"].dump() + " vs " + rb["threads"].dump();
                std::snprintf(line, sizeof line, "%-20s threads %-9s %s\n", wa["name"].get<std::string>().c_str(),
                              threads.c_str(), interval_text(r).c_str());
                text += line;
                if (by_position.size() <= i) by_position.resize(i + 1);
                by_position[i].first = rb["threads"].get<int>();
                if (r.ratio > 0) by_position[i].second.push_back(r.ratio);
            }
        }
    if (by_position.empty()) return text + "no workload in common\n";
    for (std::size_t i = 0; i < by_position.size(); ++i) {
        std::snprintf(line, sizeof line, "overall, B on %d thread(s) (geometric mean of %zu workloads): %.3f\n",
                      by_position[i].first, by_position[i].second.size(), geometric_mean(by_position[i].second));
        text += line;
    }
    return text;
}

}  // namespace isotrace::cli
