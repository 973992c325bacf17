#include "tools/cli/benchmark_html_report.h"

#include "tools/cli/benchmark_result.h"
#include "tools/cli/html_page.h"
#include "tools/cli/svg_plot.h"

namespace isotrace::cli {
namespace {

const std::vector<std::pair<const char*, const char*>> kSystemRows = {
    {"CPU", "cpu"},
    {"Sockets", "sockets"},
    {"Physical cores", "physical_cores"},
    {"Hardware threads", "hardware_threads"},
    {"SMT", "smt"},
    {"Caches", "caches"},
    {"Clock (MHz)", "clock_mhz"},
    {"Memory (bytes)", "memory_bytes"},
    {"Memory speed", "memory_speed"},
    {"Operating system", "os"},
    {"Kernel", "kernel"},
    {"Embree", "embree_version"},
    {"Embree ISA", "embree_isa"},
    {"Blob march", "blob_march_isa"},
    {"oneTBB", "tbb_version"},
    {"OpenImageIO", "oiio_version"},
    {"OpenColorIO", "ocio_version"},
    {"Compiler", "compiler"},
    {"Flags", "flags"},
    {"Build type", "build_type"},
    {"isotrace", "isotrace_version"},
    {"Commit", "commit"}};

double number_or_zero(const nlohmann::json& value) { return value.is_number() ? value.get<double>() : 0; }

// Per thread count, the workloads' scores (or units per second when there are no scores) with min-max whiskers.
std::string score_charts(const nlohmann::json& result) {
    std::string html;
    for (std::size_t i = 0; i < result["threads"].size(); ++i) {
        const bool scored = !result["workloads"].empty() && result["workloads"][0]["runs"][i]["score"].is_number();
        const char* key = scored ? "score" : "units_per_second";
        BarChart chart;
        chart.title = (scored ? "Score on " : "Units per second on ") + threads_name(result["threads"][i].get<int>());
        chart.value_label = scored ? "score (reference machine: 1000; whisker: slowest to fastest unit)"
                                   : "units per second (whisker: slowest to fastest unit)";
        for (const auto& w : result["workloads"]) {
            const auto& run = w["runs"][i];
            chart.bars.push_back({w["name"].get<std::string>(), number_or_zero(run[key]),
                                  number_or_zero(run[std::string(key) + "_min"]),
                                  number_or_zero(run[std::string(key) + "_max"])});
        }
        html += "<figure>" + svg_bar_chart(chart) + "</figure>\n";
    }
    return html;
}

std::string speedup_chart(const nlohmann::json& result) {
    if (result["threads"].size() < 2) return "<p>One thread count measured: no speed-up to show.</p>\n";
    const int threads = result["threads"].back().get<int>();
    BarChart chart;
    chart.title = "Speed-up of " + threads_name(threads) + " over 1 thread";
    chart.value_label = "units per second on " + threads_name(threads) + " over those on 1 (ideal: " +
                        std::to_string(threads) + ")";
    for (const auto& w : result["workloads"]) {
        const double one = number_or_zero(w["runs"].front()["units_per_second"]);
        const double all = number_or_zero(w["runs"].back()["units_per_second"]);
        const double speedup = one > 0 ? all / one : 0;
        chart.bars.push_back({w["name"].get<std::string>(), speedup, speedup, speedup});
    }
    return "<figure>" + svg_bar_chart(chart) + "</figure>\n";
}

std::string figures_table(const nlohmann::json& result) {
    std::string html = "<table>\n<tr>";
    for (const char* title : {"workload", "threads", "units", "seconds", "units/s", "min", "max", "score", "output"})
        html += html_cell(title, "th");
    html += "</tr>\n";
    for (const auto& w : result["workloads"])
        for (const auto& run : w["runs"]) {
            html += "<tr>" + html_cell(w["name"].get<std::string>()) + html_cell(std::to_string(run["threads"].get<int>())) +
                    html_cell(std::to_string(run["units"].get<int>()));
            for (const char* key : {"seconds", "units_per_second", "units_per_second_min", "units_per_second_max", "score"})
                html += html_cell(run[key].is_number() ? short_number(run[key].get<double>()) : "-");
            html += html_cell(w["valid"].get<bool>() ? "matches the reference" : "WRONG") + "</tr>\n";
        }
    return html + "</table>\n";
}

}  // namespace

std::string benchmark_html_report(const nlohmann::json& result) {
    std::string html = html_page_start(result["benchmark"].get<std::string>());
    if (result["mode"] == "short") html += "<p>A short run: it checks the outputs; its figures are not scores.</p>\n";
    if (!result["valid"].get<bool>()) {
        html += "<p><strong>Score void:</strong> an output differs from the reference.</p>\n<ul>\n";
        for (const auto& problem : result["problems"]) html += "<li>" + xml_escaped(problem.get<std::string>()) + "</li>\n";
        html += "</ul>\n";
    }
    html += "<h2>Scores</h2>\n<table>\n<tr>" + html_cell("threads", "th") + html_cell("score", "th") +
            html_cell("slowest to fastest units", "th") + "</tr>\n";
    for (const auto& s : result["scores"])
        html += "<tr>" + html_cell(threads_name(s["threads"].get<int>())) +
                html_cell(s["score"].is_number() ? short_number(s["score"].get<double>()) : "none") +
                html_cell(s["score"].is_number()
                              ? short_number(s["score_min"].get<double>()) + " to " + short_number(s["score_max"].get<double>())
                              : "-") +
                "</tr>\n";
    html += "</table>\n<p>Reference machine (1000): " + xml_escaped(result["reference_machine"].get<std::string>()) +
            "</p>\n";
    html += "<h2>Workloads</h2>\n" + score_charts(result) + speedup_chart(result);
    nlohmann::json readable = nlohmann::json::object();
    for (const auto& [title, key] : kSystemRows)
        readable[key] = readable_system_fact(key, result["system"].contains(key) ? result["system"][key] : nlohmann::json());
    html += "<h2>System</h2>\n" + html_facts_table(readable, kSystemRows);
    html += "<h2>All figures</h2>\n" + figures_table(result);
    return html + "</body>\n</html>\n";
}

}  // namespace isotrace::cli
