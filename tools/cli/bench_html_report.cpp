#include "tools/cli/bench_html_report.h"

#include <map>

#include "tools/cli/bench_report.h"
#include "tools/cli/html_page.h"
#include "tools/cli/svg_plot.h"

namespace isotrace::cli {
namespace {

// The machine's facts, in the order the page lists them.
const std::vector<std::pair<const char*, const char*>> kMachineRows = {
    {"CPU", "cpu"},           {"Cores", "cores"},       {"Embree ISA", "embree_isa"},
    {"Embree native packets", "embree_native_packets"}, {"Blob march", "blob_march_isa"},
    {"Embree", "embree_version"},
    {"Compiler", "compiler"}, {"Flags", "flags"},       {"Build type", "build_type"},
    {"isotrace", "isotrace_version"},                   {"Commit", "commit"}};

// One bar chart per unit, of the runs on the last (largest) thread count: median with a min–max whisker.
std::string throughput_charts(const nlohmann::json& workloads) {
    std::map<std::string, BarChart> by_unit;
    for (const auto& w : workloads) {
        const auto& run = w["runs"].back();
        const std::string unit = w["unit"].get<std::string>();
        BarChart& chart = by_unit[unit];
        chart.title = unit + " on " + std::to_string(run["threads"].get<int>()) + " thread(s)";
        chart.value_label = unit + " (bar: median; whisker: min to max)";
        chart.bars.push_back({w["name"].get<std::string>(), run["throughput"]["median"].get<double>(),
                              run["throughput"]["min"].get<double>(), run["throughput"]["max"].get<double>()});
    }
    std::string html;
    for (const auto& [unit, chart] : by_unit) html += "<figure>" + svg_bar_chart(chart) + "</figure>\n";
    return html;
}

std::string thread_scaling_plot(const nlohmann::json& report) {
    const auto& threads = report["settings"]["threads"];
    if (threads.size() < 2 || report["workloads"].empty())
        return "<p>One thread count measured: run <code>isotrace bench --threads 1,2,…</code> for the speed-up.</p>\n";
    LinePlot plot;
    plot.title = "Thread scaling";
    plot.x_label = "threads";
    plot.y_label = "speed-up over " + std::to_string(threads[0].get<int>()) + " thread(s)";
    PlotSeries ideal{"ideal", {}, true};
    for (const auto& t : threads) {
        plot.x_ticks.push_back(t.get<double>());
        ideal.points.push_back({t.get<double>(), t.get<double>() / threads[0].get<double>()});
    }
    plot.series.push_back(ideal);
    for (const auto& w : report["workloads"]) {
        PlotSeries series{w["name"].get<std::string>(), {}, false};
        for (const auto& run : w["runs"]) series.points.push_back({run["threads"].get<double>(), run["speedup"].get<double>()});
        plot.series.push_back(series);
    }
    return "<figure>" + svg_line_plot(plot) + "</figure>\n";
}

std::string element_scaling_plots(const nlohmann::json& scaling) {
    if (!scaling.is_object())
        return "<p>Not measured: run <code>isotrace bench --scaling</code> for the element-count scaling.</p>\n";
    LinePlot cost{"Time per primary ray", "blob elements (fixed density)", "ns per ray", true, {}, true, {}};
    LinePlot memory{"Memory per element", "blob elements (fixed density)", "bytes per element", true, {}, true, {}};
    PlotSeries ns{"ns per ray", {}, false}, bytes{"bytes per element", {}, false};
    for (const auto& p : scaling["points"]) {
        ns.points.push_back({p["elements"].get<double>(), p["ns_per_ray"].get<double>()});
        bytes.points.push_back({p["elements"].get<double>(), p["bytes_per_element"].get<double>()});
    }
    std::string table = "<table>\n<tr>";
    for (const char* title : {"elements", "rays", "ns per ray", "cost growth", "build ms", "bytes per element"})
        table += html_cell(title, "th");
    table += "</tr>\n";
    for (const auto& p : scaling["points"])
        table += "<tr>" + html_cell(short_number(p["elements"].get<double>())) + html_cell(short_number(p["rays"].get<double>())) +
                 html_cell(short_number(p["ns_per_ray"].get<double>())) + html_cell(short_number(p["cost_growth"].get<double>())) +
                 html_cell(short_number(p["build_seconds"].get<double>() * 1e3)) +
                 html_cell(short_number(p["bytes_per_element"].get<double>())) + "</tr>\n";
    table += "</table>\n";
    cost.series.push_back(ns);
    memory.series.push_back(bytes);
    return "<p>Blob groups generated at blobs_1k's density, primary rays on " +
           std::to_string(scaling["threads"].get<int>()) + " thread(s).</p>\n<figure>" + svg_line_plot(cost) +
           "</figure>\n<figure>" + svg_line_plot(memory) + "</figure>\n" + table;
}

std::string figures_table(const nlohmann::json& workloads) {
    std::string html = "<table>\n<tr>";
    for (const char* title : {"workload", "unit", "threads", "median", "min", "q1", "q3", "max", "speed-up",
                              "efficiency", "build ms", "peak MiB"})
        html += html_cell(title, "th");
    html += "</tr>\n";
    for (const auto& w : workloads)
        for (const auto& run : w["runs"]) {
            const auto& t = run["throughput"];
            html += "<tr>" + html_cell(w["name"].get<std::string>()) + html_cell(w["unit"].get<std::string>()) +
                    html_cell(std::to_string(run["threads"].get<int>()));
            for (const char* key : {"median", "min", "q1", "q3", "max"}) html += html_cell(short_number(t[key].get<double>()));
            html += html_cell(short_number(run["speedup"].get<double>())) +
                    html_cell(short_number(100 * run["efficiency"].get<double>()) + " %") +
                    html_cell(short_number(w["build_seconds"].get<double>() * 1e3)) +
                    html_cell(short_number(double(w["peak_memory_bytes"].get<std::uint64_t>()) / (1 << 20))) + "</tr>\n";
        }
    return html + "</table>\n";
}

}  // namespace

std::string bench_html_report(const nlohmann::json& report) {
    std::string html = html_page_start("isotrace bench");
    const auto& settings = report["settings"];
    html += "<p>Warm-up run and " + std::to_string(settings["repeats"].get<int>()) +
            " timed run(s) per workload and thread count" + (settings["quick"].get<bool>() ? " (--quick)" : "") +
            ".</p>\n";
    html += "<h2>Machine</h2>\n" + html_facts_table(report["machine"], kMachineRows);
    if (!report["workloads"].empty()) {
        html += "<h2>Throughput</h2>\n" + throughput_charts(report["workloads"]);
        html += "<h2>Thread scaling</h2>\n" + thread_scaling_plot(report);
    }
    html += "<h2>Element-count scaling</h2>\n" + element_scaling_plots(report["scaling"]);
    if (!report["workloads"].empty()) html += "<h2>All figures</h2>\n" + figures_table(report["workloads"]);
    if (report["blob_comparison"].is_object())
        html += "<h2>Blob groups: direct against tessellated</h2>\n<pre>" +
                xml_escaped(benchmark_table(report["blob_comparison"])) + "</pre>\n";
    return html + "</body>\n</html>\n";
}

}  // namespace isotrace::cli
