#include "tools/cli/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace isotrace::cli {
namespace {

// Colour-blind safe (Okabe and Ito's, then Tol's muted), repeated for more series.
constexpr const char* kPalette[] = {"#0072B2", "#E69F00", "#009E73", "#D55E00", "#CC79A7", "#56B4E9", "#F0E442",
                                    "#000000", "#882255", "#44AA99", "#999933", "#332288"};
constexpr int kPaletteSize = sizeof kPalette / sizeof kPalette[0];

std::string number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", value);
    return buffer;
}

std::string text_element(double x, double y, const std::string& text, const char* anchor, int size = 12,
                         const std::string& extra = "") {
    return "<text x=\"" + number(x) + "\" y=\"" + number(y) + "\" font-size=\"" + std::to_string(size) +
           "\" text-anchor=\"" + anchor + "\"" + extra + ">" + xml_escaped(text) + "</text>\n";
}

std::string line_element(double x0, double y0, double x1, double y1, const char* stroke, const std::string& extra = "") {
    return "<line x1=\"" + number(x0) + "\" y1=\"" + number(y0) + "\" x2=\"" + number(x1) + "\" y2=\"" + number(y1) +
           "\" stroke=\"" + stroke + "\"" + extra + "/>\n";
}

std::string svg_open(double width, double height) {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "\" height=\"" + number(height) +
           "\" viewBox=\"0 0 " + number(width) + " " + number(height) + "\" font-family=\"sans-serif\">\n" +
           "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

// Maps data to pixels on one axis, linearly or by log10.
struct Axis {
    double low, high, pixel_low, pixel_high;
    bool log;
    double operator()(double v) const {
        const double t = log ? (std::log10(v) - std::log10(low)) / (std::log10(high) - std::log10(low))
                             : (v - low) / (high - low);
        return pixel_low + t * (pixel_high - pixel_low);
    }
};

// [low, high] widened to a non-empty range.
void widen(double& low, double& high, bool log) {
    if (high > low) return;
    if (log) {
        low /= 2;
        high *= 2;
    } else {
        low -= 0.5;
        high += 0.5;
    }
}

}  // namespace

std::string xml_escaped(const std::string& text) {
    std::string out;
    for (char c : text) switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    return out;
}

std::string short_number(double value) {
    char buffer[32];
    const double magnitude = std::abs(value);
    if (magnitude < 1e12 && value == std::round(value))  // element counts: 100000, not 1e+05
        std::snprintf(buffer, sizeof buffer, "%.0f", value);
    else
        std::snprintf(buffer, sizeof buffer, magnitude >= 1e-3 && magnitude < 1e6 ? "%.4g" : "%.3e", value);
    return buffer;
}

std::vector<double> nice_ticks(double low, double high, int count) {
    if (!(high > low) || count < 1 || !std::isfinite(low) || !std::isfinite(high)) return {low};
    const double raw = (high - low) / count;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    const double fraction = raw / power;
    const double step = (fraction <= 1 ? 1 : fraction <= 2 ? 2 : fraction <= 5 ? 5 : 10) * power;
    std::vector<double> ticks;
    for (double tick = std::ceil(low / step - 1e-9) * step; tick <= high + step * 1e-9 && ticks.size() < 100;
         tick += step)
        ticks.push_back(std::abs(tick) < step * 1e-9 ? 0.0 : tick);
    return ticks;
}

std::string svg_line_plot(const LinePlot& plot) {
    double x_low = std::numeric_limits<double>::infinity(), x_high = -x_low, y_high = 0;
    for (const PlotSeries& s : plot.series)
        for (const PlotPoint& p : s.points) {
            if (plot.log_x && !(p.x > 0)) continue;
            x_low = std::min(x_low, p.x);
            x_high = std::max(x_high, p.x);
            y_high = std::max(y_high, p.y);
        }
    if (!std::isfinite(x_low)) x_low = x_high = 1;
    widen(x_low, x_high, plot.log_x);
    const double headroom = plot.label_points ? 1.15 : 1.05;  // room for the labels above the highest points
    const std::vector<double> y_ticks = nice_ticks(0, y_high > 0 ? y_high * headroom : 1, 5);
    const double y_top = std::max(y_ticks.back(), y_high * headroom);

    const double left = 70, plot_width = 440, top = 40, legend_width = 230;
    const double legend_height = 18.0 * double(plot.series.size());
    const double plot_height = std::max(260.0, legend_height);
    const double width = left + plot_width + legend_width, height = top + plot_height + 55;
    const Axis x{x_low, x_high, left, left + plot_width, plot.log_x};
    const Axis y{0, y_top, top + plot_height, top, false};

    std::string svg = svg_open(width, height);
    svg += text_element(left + plot_width / 2, 22, plot.title, "middle", 15, " font-weight=\"bold\"");
    std::vector<double> x_ticks = plot.x_ticks;
    if (x_ticks.empty() && plot.log_x) {
        for (double t = std::pow(10.0, std::floor(std::log10(x_low))); t <= x_high * 1.0001; t *= 10)
            if (t >= x_low * 0.9999) x_ticks.push_back(t);
    } else if (x_ticks.empty()) {
        x_ticks = nice_ticks(x_low, x_high, 6);
    }
    for (double t : x_ticks) {
        svg += line_element(x(t), top, x(t), top + plot_height, "#e4e4e4");
        svg += text_element(x(t), top + plot_height + 16, short_number(t), "middle", 11);
    }
    for (double t : y_ticks) {
        svg += line_element(left, y(t), left + plot_width, y(t), "#e4e4e4");
        svg += text_element(left - 6, y(t) + 4, short_number(t), "end", 11);
    }
    svg += line_element(left, top + plot_height, left + plot_width, top + plot_height, "#444444");
    svg += line_element(left, top, left, top + plot_height, "#444444");
    svg += text_element(left + plot_width / 2, top + plot_height + 40, plot.x_label, "middle", 12);
    svg += text_element(18, top + plot_height / 2, plot.y_label, "middle", 12,
                        " transform=\"rotate(-90 18 " + number(top + plot_height / 2) + ")\"");

    int colour = 0;
    for (std::size_t i = 0; i < plot.series.size(); ++i) {
        const PlotSeries& s = plot.series[i];
        const char* stroke = s.dashed ? "#888888" : kPalette[colour++ % kPaletteSize];
        const std::string dash = s.dashed ? " stroke-dasharray=\"6 4\"" : "";
        std::string points;
        for (const PlotPoint& p : s.points)
            if (!plot.log_x || p.x > 0) points += number(x(p.x)) + "," + number(y(p.y)) + " ";
        svg += "<polyline points=\"" + points + "\" fill=\"none\" stroke=\"" + stroke + "\" stroke-width=\"2\"" +
               dash + "/>\n";
        if (!s.dashed)
            for (const PlotPoint& p : s.points)
                if (!plot.log_x || p.x > 0) {
                    svg += "<circle cx=\"" + number(x(p.x)) + "\" cy=\"" + number(y(p.y)) + "\" r=\"3\" fill=\"" +
                           stroke + "\"/>\n";
                    if (plot.label_points) svg += text_element(x(p.x) + 6, y(p.y) - 8, short_number(p.y), "start", 11);
                }
        const double legend_y = top + 18.0 * double(i) + 6;
        svg += line_element(left + plot_width + 16, legend_y, left + plot_width + 40, legend_y, stroke,
                            " stroke-width=\"2\"" + dash);
        svg += text_element(left + plot_width + 46, legend_y + 4, s.label, "start", 11);
    }
    return svg + "</svg>\n";
}

std::string svg_bar_chart(const BarChart& chart) {
    double high = 0;
    for (const Bar& b : chart.bars) high = std::max({high, b.value, b.high});
    const std::vector<double> ticks = nice_ticks(0, high > 0 ? high * 1.05 : 1, 5);
    const double top_value = std::max(ticks.back(), high);
    const double label_width = 230, chart_width = 420, top = 40, row = 22;
    const double height = top + row * double(chart.bars.size()) + 50, width = label_width + chart_width + 90;
    const Axis x{0, top_value, label_width, label_width + chart_width, false};
    const double bottom = top + row * double(chart.bars.size());

    std::string svg = svg_open(width, height);
    svg += text_element(width / 2, 22, chart.title, "middle", 15, " font-weight=\"bold\"");
    for (double t : ticks) {
        svg += line_element(x(t), top, x(t), bottom, "#e4e4e4");
        svg += text_element(x(t), bottom + 16, short_number(t), "middle", 11);
    }
    svg += text_element(label_width + chart_width / 2, bottom + 38, chart.value_label, "middle", 12);
    for (std::size_t i = 0; i < chart.bars.size(); ++i) {
        const Bar& b = chart.bars[i];
        const double y = top + row * double(i);
        svg += text_element(label_width - 8, y + row / 2 + 4, b.label, "end", 12);
        svg += "<rect x=\"" + number(label_width) + "\" y=\"" + number(y + 3) + "\" width=\"" +
               number(x(std::max(b.value, 0.0)) - label_width) + "\" height=\"" + number(row - 6) + "\" fill=\"" +
               kPalette[0] + "\"/>\n";
        if (b.high > b.low) {
            const double middle = y + row / 2;
            svg += line_element(x(b.low), middle, x(b.high), middle, "#222222", " stroke-width=\"1.5\"");
            svg += line_element(x(b.low), middle - 5, x(b.low), middle + 5, "#222222", " stroke-width=\"1.5\"");
            svg += line_element(x(b.high), middle - 5, x(b.high), middle + 5, "#222222", " stroke-width=\"1.5\"");
        }
        svg += text_element(x(std::max(b.value, b.high)) + 6, y + row / 2 + 4, short_number(b.value), "start", 11);
    }
    svg += line_element(label_width, top, label_width, bottom, "#444444");
    return svg + "</svg>\n";
}

}  // namespace isotrace::cli
