#pragma once
// Small self-contained SVG charts for isotrace bench --report: a line plot (linear or logarithmic x axis) and a
// horizontal bar chart with whiskers. Plain SVG 1.1 text: no scripts, fonts or external references.
#include <string>
#include <vector>

namespace isotrace::cli {

struct PlotPoint {
    double x = 0, y = 0;
};

struct PlotSeries {
    std::string label;
    std::vector<PlotPoint> points;
    bool dashed = false;  // a reference line (ideal scaling), drawn grey and dashed
};

struct LinePlot {
    std::string title, x_label, y_label;
    bool log_x = false;  // x values must then be > 0
    std::vector<double> x_ticks;  // where to mark the x axis (thread counts, say); empty: round values
    bool label_points = false;    // write each measured point's y value beside it (for plots with few points)
    std::vector<PlotSeries> series;
};

struct Bar {
    std::string label;
    double value = 0;
    double low = 0, high = 0;  // the whisker; low = high = value draws none
};

struct BarChart {
    std::string title, value_label;
    std::vector<Bar> bars;
};

std::string svg_line_plot(const LinePlot& plot);
std::string svg_bar_chart(const BarChart& chart);

// Text safe inside XML elements and attribute values: & < > " ' escaped.
std::string xml_escaped(const std::string& text);

// About `count` round tick values (1, 2 or 5 times a power of ten) covering [low, high].
std::vector<double> nice_ticks(double low, double high, int count);

// A number for an axis or a label: whole numbers in full, others with 4 significant digits and no exponent for
// 1e-3 ≤ |v| < 1e6.
std::string short_number(double value);

}  // namespace isotrace::cli
