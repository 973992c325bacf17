#include "tools/cli/svg_plot.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tools/cli/well_formed_markup_test.h"

namespace isotrace::cli {

namespace {

TEST(SvgPlot, EscapesMarkup) { EXPECT_EQ(xml_escaped("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;"); }

TEST(SvgPlot, NiceTicksAreRoundAndCoverTheRange) {
    EXPECT_EQ(nice_ticks(0, 10, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
    EXPECT_EQ(nice_ticks(0, 0.9, 3), (std::vector<double>{0, 0.5}));
    const std::vector<double> ticks = nice_ticks(0, 43, 5);
    EXPECT_EQ(ticks.front(), 0);
    EXPECT_EQ(ticks[1], 10);
    EXPECT_EQ(nice_ticks(1, 1, 5), std::vector<double>{1});  // an empty range: no loop
}

TEST(SvgPlot, ShortNumbers) {
    EXPECT_EQ(short_number(12.3456), "12.35");
    EXPECT_EQ(short_number(0), "0");
    EXPECT_EQ(short_number(2.5e7), "25000000");
    EXPECT_EQ(short_number(2.5e7 + 0.5), "2.500e+07");
    EXPECT_EQ(short_number(1.5e-5), "1.500e-05");
}

TEST(SvgPlot, LinePlotIsWellFormedAndNamesItsSeries) {
    LinePlot plot;
    plot.title = "Thread scaling <test>";
    plot.x_label = "threads";
    plot.y_label = "speed-up";
    plot.x_ticks = {1, 2, 4};
    plot.series = {{"ideal", {{1, 1}, {2, 2}, {4, 4}}, true}, {"cornell_box/primary", {{1, 1}, {2, 1.9}, {4, 3.5}}, false}};
    const std::string svg = svg_line_plot(plot);
    EXPECT_TRUE(well_formed_markup(svg));
    EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
    EXPECT_NE(svg.find("Thread scaling &lt;test&gt;"), std::string::npos);
    EXPECT_NE(svg.find("cornell_box/primary"), std::string::npos);
    EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);  // the ideal line
    EXPECT_EQ(std::count(svg.begin(), svg.end(), '\n') > 10, true);
    // Three markers for the measured series, none for the reference line.
    std::size_t circles = 0;
    for (std::size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
    EXPECT_EQ(circles, 3u);
}

TEST(SvgPlot, LogAxisTicksArePowersOfTen) {
    LinePlot plot{"cost", "elements", "ns", true, {}, true, {{"ns per ray", {{1000, 50}, {10000, 60}, {100000, 80}}, false}}};
    const std::string svg = svg_line_plot(plot);
    EXPECT_TRUE(well_formed_markup(svg));
    for (const char* tick : {">1000<", ">10000<", ">100000<"}) EXPECT_NE(svg.find(tick), std::string::npos) << tick;
    for (const char* value : {">50<", ">60<", ">80<"}) EXPECT_NE(svg.find(value), std::string::npos) << value;
}

TEST(SvgPlot, BarChartShowsValuesAndWhiskers) {
    BarChart chart{"Mrays/s", "Mrays/s", {{"blobs_1k/primary", 12.5, 11, 13}, {"csg_cup/primary", 3.25, 3.25, 3.25}}};
    const std::string svg = svg_bar_chart(chart);
    EXPECT_TRUE(well_formed_markup(svg));
    EXPECT_NE(svg.find(">12.5<"), std::string::npos);
    EXPECT_NE(svg.find(">3.25<"), std::string::npos);
    EXPECT_NE(svg.find(">blobs_1k/primary<"), std::string::npos);
    std::size_t rects = 0;
    for (std::size_t at = svg.find("<rect"); at != std::string::npos; at = svg.find("<rect", at + 1)) ++rects;
    EXPECT_EQ(rects, 3u);  // background and two bars
}

TEST(SvgPlot, WellFormedCheckCatchesMistakes) {
    EXPECT_FALSE(well_formed_markup("<svg><g></svg>"));
    EXPECT_FALSE(well_formed_markup("<svg>a < b</svg>"));
    EXPECT_FALSE(well_formed_markup("<svg>a & b</svg>"));
    EXPECT_TRUE(well_formed_markup("<svg><line/></svg>"));
}

}  // namespace
}  // namespace isotrace::cli
