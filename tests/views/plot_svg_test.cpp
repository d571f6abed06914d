#include "views/plot_svg.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/svg_check.hpp"

namespace crux {
namespace {

using testing::check_well_formed;
using testing::count_of;

// The value of the first `name` attribute at or after `from`.
std::string attribute_after(const std::string& svg, std::size_t from, const std::string& name) {
  const std::size_t at = svg.find(" " + name + "=\"", from);
  if (at == std::string::npos) throw std::runtime_error("no " + name);
  const std::size_t value = at + name.size() + 3;
  return svg.substr(value, svg.find('"', value) - value);
}

TEST(PlotSvgTest, Log10AxisSpansWholeDecadesAndAddsTwoAndFiveOnShortOnes) {
  const Axis wide = log10_axis(12, 1500, "length");
  EXPECT_DOUBLE_EQ(wide.low, 10);
  EXPECT_DOUBLE_EQ(wide.high, 10000);
  EXPECT_EQ(wide.tick_labels, (std::vector<std::string>{"10", "100", "1000", "10000"}));

  const Axis narrow = log10_axis(3, 40, "length");
  EXPECT_DOUBLE_EQ(narrow.low, 1);
  EXPECT_DOUBLE_EQ(narrow.high, 100);
  EXPECT_EQ(narrow.tick_labels, (std::vector<std::string>{"1", "2", "5", "10", "20", "50", "100"}));

  const Axis fractions = log10_axis(0.05, 0.5, "rate");
  EXPECT_EQ(fractions.tick_labels, (std::vector<std::string>{"0.01", "0.02", "0.05", "0.1", "0.2", "0.5", "1"}));

  const Axis exact = log10_axis(10, 10, "one decade");
  EXPECT_DOUBLE_EQ(exact.low, 10);
  EXPECT_DOUBLE_EQ(exact.high, 100);

  EXPECT_THROW(log10_axis(0, 10, "zero"), std::invalid_argument);
  EXPECT_THROW(log10_axis(-1, 10, "negative"), std::invalid_argument);
}

TEST(PlotSvgTest, PanelMapsLinearAndLogAxesAndClampsToTheirEdges) {
  Panel panel{100, 50, 200, 300, linear_axis(0, 10, "x"), log10_axis(1, 1000, "y")};
  ASSERT_DOUBLE_EQ(panel.x.high, 10);
  EXPECT_DOUBLE_EQ(panel.x_pixel(0), 100);
  EXPECT_DOUBLE_EQ(panel.x_pixel(5), 200);
  EXPECT_DOUBLE_EQ(panel.x_pixel(10), 300);
  EXPECT_DOUBLE_EQ(panel.x_pixel(-3), 100);
  EXPECT_DOUBLE_EQ(panel.x_pixel(42), 300);
  // y: 1 at the bottom (350), 1000 at the top (50), one decade per 100 pixels.
  EXPECT_DOUBLE_EQ(panel.y_pixel(1), 350);
  EXPECT_DOUBLE_EQ(panel.y_pixel(10), 250);
  EXPECT_DOUBLE_EQ(panel.y_pixel(1000), 50);
  EXPECT_NEAR(panel.y_pixel(std::sqrt(10.0)), 300, 1e-9);
  EXPECT_DOUBLE_EQ(panel.y_pixel(0), 350);  // below a log axis: its bottom edge
  EXPECT_DOUBLE_EQ(panel.y_pixel(-5), 350);
  EXPECT_DOUBLE_EQ(panel.y_pixel(1e6), 50);
}

TEST(PlotSvgTest, PolylinesBreakAtMissingValuesAndBandsGoAlongHighThenBackAlongLow) {
  const Panel panel{0, 0, 100, 100, linear_axis(0, 10, ""), linear_axis(0, 10, "")};
  const double nan = std::nan("");
  std::string svg;
  draw_polyline(svg, panel, {1, 2, 3, 4, 5, 6}, {1, 2, nan, 4, 5, nan}, {"#123456", 2, "4 2"});
  EXPECT_EQ(count_of(svg, "<polyline"), 2);
  EXPECT_EQ(attribute_after(svg, 0, "points"), "10.00,90.00 20.00,80.00");
  EXPECT_NE(svg.find("stroke-dasharray=\"4 2\""), std::string::npos);

  svg.clear();
  draw_polyline(svg, panel, {1, 2, 3}, {1, nan, 3}, {"#123456", 2, ""});
  EXPECT_EQ(count_of(svg, "<polyline"), 0);
  EXPECT_EQ(count_of(svg, "<circle"), 2);  // lone points stay visible

  svg.clear();
  draw_band(svg, panel, {0, 5, 10}, {1, 2, 3}, {4, 5, 6}, "#abcdef");
  EXPECT_EQ(count_of(svg, "<polygon"), 1);
  EXPECT_EQ(attribute_after(svg, 0, "points"),
            "0.00,60.00 50.00,50.00 100.00,40.00 100.00,70.00 50.00,80.00 0.00,90.00");
  EXPECT_EQ(attribute_after(svg, 0, "fill"), "#abcdef");

  svg.clear();
  draw_band(svg, panel, {0, 5, 10}, {1, nan, 3}, {4, 5, 6}, "#abcdef");
  EXPECT_EQ(count_of(svg, "<polygon"), 0);  // pieces of one point have no area

  EXPECT_THROW(draw_polyline(svg, panel, {1, 2}, {1}, {}), std::invalid_argument);
  EXPECT_THROW(draw_band(svg, panel, {1, 2}, {1, 2}, {1}, "#000000"), std::invalid_argument);
}

TEST(PlotSvgTest, ReferenceLinesAndErrorBarsSitWhereTheDataSays) {
  const Panel panel{10, 20, 100, 50, linear_axis(-10, 10, ""), linear_axis(0, 5, "")};
  std::string svg;
  draw_reference_line(svg, panel, Direction::Vertical, 0, {"#444444", 1, "5 4"});
  EXPECT_EQ(attribute_after(svg, 0, "x1"), "60.00");
  EXPECT_EQ(attribute_after(svg, 0, "y1"), "20.00");
  EXPECT_EQ(attribute_after(svg, 0, "y2"), "70.00");
  svg.clear();
  draw_reference_line(svg, panel, Direction::Horizontal, 2.5, {"#444444", 1, "5 4"});
  EXPECT_EQ(attribute_after(svg, 0, "y1"), "45.00");
  EXPECT_EQ(attribute_after(svg, 0, "x2"), "110.00");
  svg.clear();
  draw_point_with_error_bar(svg, panel, 5, -5, 10, 1, "#0072b2");
  const std::size_t bar = svg.find("<line");
  EXPECT_EQ(attribute_after(svg, bar, "x1"), "35.00");
  EXPECT_EQ(attribute_after(svg, bar, "x2"), "110.00");
  EXPECT_EQ(attribute_after(svg, svg.find("<circle"), "cx"), "85.00");
  EXPECT_EQ(attribute_after(svg, svg.find("<circle"), "cy"), "60.00");
}

TEST(PlotSvgTest, DivergingColoursAreWhiteAtZeroAndSpreadEachSideOverItsOwnRange) {
  const DivergingScale scale{-10, 1000};
  EXPECT_DOUBLE_EQ(diverging_position(scale, 0), 0.5);
  EXPECT_DOUBLE_EQ(diverging_position(scale, -5), 0.25);
  EXPECT_DOUBLE_EQ(diverging_position(scale, 500), 0.75);
  EXPECT_DOUBLE_EQ(diverging_position(scale, -20), 0);  // beyond the scale: its end
  EXPECT_EQ(diverging_colour(scale, 0), "#f7f7f7");
  EXPECT_EQ(diverging_colour(scale, -10), "#2166ac");
  EXPECT_EQ(diverging_colour(scale, 1000), "#b2182b");
  // Position 0.25 lies halfway between the stops #67a9cf and #d1e5f0.
  EXPECT_EQ(diverging_colour(scale, -5), "#9cc7e0");
  EXPECT_EQ(diverging_colour(DivergingScale{0, 10}, -1), "#f7f7f7");  // no negative side
}

TEST(PlotSvgTest, ColourBarLabelsZeroAndBothSidesWithoutOverlap) {
  std::string svg;
  draw_colour_bar(svg, 0, 0, 300, DivergingScale{-6000, 1000000}, "value");
  EXPECT_NE(svg.find(">0</text>"), std::string::npos);
  EXPECT_NE(svg.find(">1.0M</text>"), std::string::npos);
  EXPECT_NE(svg.find(">value</text>"), std::string::npos);
  EXPECT_EQ(check_well_formed("<svg xmlns=\"http://www.w3.org/2000/svg\">" + svg + "</svg>"), "");
  // Label centres at least a label's width apart.
  std::vector<double> centres;
  const std::size_t ticks = svg.find("class=\"colour-bar-ticks\"");
  for (std::size_t at = svg.find("<text", ticks); at != std::string::npos && at < svg.find("</g>", ticks);
       at = svg.find("<text", at + 1)) {
    centres.push_back(std::stod(attribute_after(svg, at, "x")));
  }
  ASSERT_GE(centres.size(), 3u);
  std::sort(centres.begin(), centres.end());
  for (std::size_t i = 1; i < centres.size(); ++i) EXPECT_GT(centres[i] - centres[i - 1], 20);
}

TEST(PlotSvgTest, DocumentIsStandaloneSvgWithEscapedText) {
  const Panel panel{60, 20, 200, 100, linear_axis(0, 100, "x (m)"), log10_axis(1, 100, "y (s)")};
  std::string body;
  draw_axes(body, panel);
  draw_text(body, 5, 5, "a < b & \"c\"", {.bold = true});
  draw_legend(body, 300, 20,
              {{LegendMark::LineWithBand, "#0072b2", "", "mean & band"}, {LegendMark::Point, "#000000", "", "P_i"}});
  const std::string svg = svg_document(400.2, 200, "plot <1>", body);
  EXPECT_EQ(check_well_formed(svg), "");
  EXPECT_NE(svg.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  EXPECT_NE(svg.find("version=\"1.1\" width=\"401\" height=\"200\" viewBox=\"0 0 401 200\""), std::string::npos);
  EXPECT_NE(svg.find("<title>plot &lt;1&gt;</title>"), std::string::npos);
  EXPECT_NE(svg.find(">a &lt; b &amp; &quot;c&quot;</text>"), std::string::npos);
  EXPECT_NE(svg.find(">mean &amp; band</text>"), std::string::npos);
  EXPECT_NE(svg.find(">x (m)</text>"), std::string::npos);
  EXPECT_NE(svg.find("rotate(-90.0"), std::string::npos);  // the y title
  EXPECT_GT(legend_width({{LegendMark::Line, "#000000", "", "a longer legend text"}}),
            legend_width({{LegendMark::Line, "#000000", "", "short"}}));
  EXPECT_DOUBLE_EQ(legend_height({{}, {}, {}}), 60);
}

}  // namespace
}  // namespace crux
