#include "tools/cli/benchmark_result.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace isotrace::cli {
namespace {

nlohmann::json score_or_null(double rate, double reference_rate, bool valid) {
    return valid && reference_rate > 0 && rate > 0 ? nlohmann::json(1000 * rate / reference_rate) : nlohmann::json();
}

nlohmann::json run_json(const BenchmarkRun& run, double reference_rate, bool valid) {
    const double seconds = std::accumulate(run.seconds.begin(), run.seconds.end(), 0.0);
    const double units = double(run.seconds.size());
    const auto [fastest, slowest] = std::minmax_element(run.seconds.begin(), run.seconds.end());
    const double rate = seconds > 0 ? units / seconds : 0;
    const double low = run.seconds.empty() || *slowest <= 0 ? 0 : 1 / *slowest;
    const double high = run.seconds.empty() || *fastest <= 0 ? 0 : 1 / *fastest;
    return {{"threads", run.threads},
            {"units", run.seconds.size()},
            {"seconds", seconds},
            {"unit_seconds", run.seconds},
            {"units_per_second", rate},
            {"units_per_second_min", low},
            {"units_per_second_max", high},
            {"score", score_or_null(rate, reference_rate, valid)},
            {"score_min", score_or_null(low, reference_rate, valid)},
            {"score_max", score_or_null(high, reference_rate, valid)}};
}

// The geometric mean of every workload's `key` at the i-th thread count; null unless all are numbers.
nlohmann::json overall(const nlohmann::json& workloads, std::size_t i, const char* key) {
    std::vector<double> values;
    for (const auto& w : workloads) {
        if (i >= w["runs"].size() || !w["runs"][i][key].is_number()) return nullptr;
        values.push_back(w["runs"][i][key].get<double>());
    }
    return values.empty() ? nlohmann::json() : nlohmann::json(geometric_mean(values));
}

std::string figure(const nlohmann::json& value, const char* format) {
    if (!value.is_number()) return "-";
    char text[32];
    std::snprintf(text, sizeof text, format, value.get<double>());
    return text;
}

std::string bytes_text(std::uint64_t bytes) {
    char text[32];
    if (bytes >= (std::uint64_t(1) << 30)) std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1 << 30));
    else if (bytes >= (std::uint64_t(1) << 20)) std::snprintf(text, sizeof text, "%.0f MiB", double(bytes) / double(1 << 20));
    else std::snprintf(text, sizeof text, "%.0f KiB", double(bytes) / 1024);
    return text;
}

// The facts of `keys`, readable, after their labels: "CPU AMD EPYC, sockets 1, ...".
std::string facts_line(const nlohmann::json& system, std::initializer_list<std::pair<const char*, const char*>> keys) {
    std::string line;
    for (const auto& [label, key] : keys)
        line += std::string(line.empty() ? "" : ", ") + label + " " +
                readable_system_fact(key, system.is_object() && system.contains(key) ? system[key] : nlohmann::json());
    return line + "\n";
}

std::string system_lines(const nlohmann::json& system) {
    return facts_line(system, {{"CPU", "cpu"},
                               {"sockets", "sockets"},
                               {"cores", "physical_cores"},
                               {"hardware threads", "hardware_threads"},
                               {"SMT", "smt"}}) +
           facts_line(system, {{"caches", "caches"}, {"clock", "clock_mhz"}, {"memory", "memory_bytes"}}) +
           facts_line(system, {{"OS", "os"}, {"kernel", "kernel"}}) +
           facts_line(system, {{"isotrace", "isotrace_version"},
                               {"commit", "commit"},
                               {"compiler", "compiler"},
                               {"Embree", "embree_version"},
                               {"on", "embree_isa"}});
}

}  // namespace

std::string readable_system_fact(const std::string& key, const nlohmann::json& value) {
    if (value.is_null()) return "unknown";
    if (value.is_string()) return value.get<std::string>();
    if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
    std::string text;
    if (key == "caches" && value.is_array()) {
        for (const auto& c : value)
            text += (text.empty() ? "L" : ", L") + c["level"].dump() + " " + c["type"].get<std::string>() + " " +
                    bytes_text(c["bytes"].get<std::uint64_t>()) + " x" + c["count"].dump();
        return text.empty() ? "unknown" : text;
    }
    if (key == "clock_mhz" && value.is_object()) {
        for (const auto& [name, mhz] : value.items())
            if (mhz.is_number()) text += (text.empty() ? "" : ", ") + name + " " + figure(mhz, "%.0f") + " MHz";
        return text.empty() ? "unknown" : text;
    }
    if (key == "memory_bytes" && value.is_number_unsigned()) return bytes_text(value.get<std::uint64_t>());
    return value.dump();
}

std::string threads_name(int threads) { return std::to_string(threads) + (threads == 1 ? " thread" : " threads"); }

double geometric_mean(const std::vector<double>& values) {
    if (values.empty()) return 0;
    double log_sum = 0;
    for (double v : values) log_sum += std::log(v);
    return std::exp(log_sum / double(values.size()));
}

nlohmann::json benchmark_result_json(const std::vector<BenchmarkWorkloadResult>& results,
                                     const BenchmarkReferences& references, bool short_mode,
                                     const nlohmann::json& system) {
    nlohmann::json result = {{"benchmark", kBenchmarkSuite},
                             {"result_format", kBenchmarkResultFormat},
                             {"mode", short_mode ? "short" : "full"},
                             {"valid", true},
                             {"problems", nlohmann::json::array()},
                             {"system", system},
                             {"reference_machine", references.machine},
                             {"threads", nlohmann::json::array()},
                             {"workloads", nlohmann::json::array()},
                             {"scores", nlohmann::json::array()}};
    const std::string embree_isa = system.is_object() ? system.value("embree_isa", "") : "";
    for (const BenchmarkWorkloadResult& r : results) {
        const BenchmarkReference& reference = references.workloads.at(r.workload->name);
        const std::string& reference_hash = reference.hash_for(embree_isa);
        std::set<std::string> hashes;
        for (const BenchmarkRun& run : r.runs) hashes.insert(run.hashes.begin(), run.hashes.end());
        const bool valid = hashes.size() == 1 && *hashes.begin() == reference_hash;
        if (hashes.size() > 1)
            result["problems"].push_back(r.workload->name + ": the units gave " + std::to_string(hashes.size()) +
                                         " different outputs (a deterministic computation came out differently)");
        else if (!valid)
            result["problems"].push_back(r.workload->name + ": the output (hash " +
                                         (hashes.empty() ? "none" : *hashes.begin()) +
                                         ") is not the reference output (hash " + reference_hash + ")");
        result["valid"] = result["valid"].get<bool>() && valid;
        nlohmann::json workload = {{"name", r.workload->name},
                                   {"measures", r.workload->measures},
                                   {"units_per_run", r.workload->units},
                                   {"hash", hashes.size() == 1 ? nlohmann::json(*hashes.begin()) : nlohmann::json()},
                                   {"reference_hash", reference_hash},
                                   {"valid", valid},
                                   {"runs", nlohmann::json::array()}};
        // A short run (one unit, no warm-up) checks the outputs; its times are not scored.
        for (const BenchmarkRun& run : r.runs)
            workload["runs"].push_back(run_json(
                run, run.threads == 1 ? reference.single_thread_rate : reference.all_threads_rate, valid && !short_mode));
        result["workloads"].push_back(workload);
    }
    // A score stands only for a valid result of the whole suite.
    const bool whole = results.size() == benchmark_workloads().size();
    if (!results.empty())
        for (std::size_t i = 0; i < results.front().runs.size(); ++i) {
            const int threads = results.front().runs[i].threads;
            result["threads"].push_back(threads);
            const bool scored = whole && result["valid"].get<bool>();
            result["scores"].push_back({{"threads", threads},
                                        {"score", scored ? overall(result["workloads"], i, "score") : nullptr},
                                        {"score_min", scored ? overall(result["workloads"], i, "score_min") : nullptr},
                                        {"score_max", scored ? overall(result["workloads"], i, "score_max") : nullptr}});
        }
    return result;
}

std::string benchmark_summary(const nlohmann::json& result) {
    std::string text = result["benchmark"].get<std::string>() +
                       (result["mode"] == "short" ? " (short run: checks the outputs; its figures are not scores to quote)"
                                                  : "") +
                       "\n\n";
    text += system_lines(result["system"]) + "\n";
    char line[256];
    std::snprintf(line, sizeof line, "%-20s", "workload");
    text += line;
    for (const auto& t : result["threads"]) {
        std::snprintf(line, sizeof line, "  %-32s", (threads_name(t.get<int>()) + ": units/s (min-max)  score").c_str());
        text += line;
    }
    text += "  output\n";
    for (const auto& w : result["workloads"]) {
        std::snprintf(line, sizeof line, "%-20s", w["name"].get<std::string>().c_str());
        text += line;
        for (const auto& run : w["runs"]) {
            const std::string rate = figure(run["units_per_second"], "%.3f") + " (" +
                                     figure(run["units_per_second_min"], "%.3f") + "-" +
                                     figure(run["units_per_second_max"], "%.3f") + ")";
            std::snprintf(line, sizeof line, "  %-26s %5s", rate.c_str(), figure(run["score"], "%.0f").c_str());
            text += line;
        }
        text += w["valid"].get<bool>() ? "  ok\n" : "  WRONG\n";
    }
    text += "\n";
    if (!result["valid"].get<bool>()) {
        text += "SCORE VOID: an output differs from the reference, so the figures above measure other work:\n";
        for (const auto& problem : result["problems"]) text += "  " + problem.get<std::string>() + "\n";
        return text;
    }
    if (result["mode"] == "short") return text + "No scores: a short run only checks the outputs.\n";
    for (const auto& s : result["scores"]) {
        if (s["score"].is_null()) {
            text += "Score (" + threads_name(s["threads"].get<int>()) +
                    "): none (a score needs every workload and the reference machine's rates)\n";
            continue;
        }
        std::snprintf(line, sizeof line, "Score (%s): %.0f  (from slowest to fastest units: %.0f-%.0f)\n",
                      threads_name(s["threads"].get<int>()).c_str(), s["score"].get<double>(),
                      s["score_min"].get<double>(), s["score_max"].get<double>());
        text += line;
    }
    return text;
}

}  // namespace isotrace::cli
