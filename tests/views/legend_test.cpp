#include "views/legend.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "support/svg_check.hpp"

namespace crux {
namespace {

using testing::count_of;

// A mark that writes where it was drawn.
LegendItem item(std::string text) {
  return {std::move(text), [](std::string& svg, double x, double y) { svg += fmt::format("<mark x={} y={}/>", x, y); }};
}

TEST(LegendTest, AColumnPutsOneItemPerRowWithItsTextAfterTheMark) {
  std::string svg;
  draw_legend_column(svg, 100, 50, {item("a & b"), item("c")}, {.font_size = 12, .mark_width = 38, .row_height = 20});
  EXPECT_EQ(svg,
            "<g class=\"legend\">\n"
            "<mark x=100 y=60/><text x=\"138.00\" y=\"64.00\" font-size=\"12\" fill=\"#333333\">a &amp; b</text>\n"
            "<mark x=100 y=80/><text x=\"138.00\" y=\"84.00\" font-size=\"12\" fill=\"#333333\">c</text>\n"
            "</g>\n");
}

TEST(LegendTest, TheViewsSetTheFontOnceOnTheGroup) {
  std::string svg;
  draw_legend_column(svg, 0, 0, {item("hold")},
                     {.font_size = 11, .mark_width = 30, .row_height = 24, .font_on_group = true});
  EXPECT_EQ(svg,
            "<g class=\"legend\" font-size=\"11\" fill=\"#333333\">\n"
            "<mark x=0 y=12/><text x=\"30.00\" y=\"16.00\">hold</text>\n"
            "</g>\n");
}

TEST(LegendTest, WidthIsTheMarkAndTheWidestText) {
  const LegendLayout layout{.font_size = 10, .mark_width = 32};
  EXPECT_DOUBLE_EQ(legend_width({"abc", "abcdef"}, layout), 32 + 6 * 6.0);
}

TEST(LegendTest, FlowingItemsWrapAtThePageAndAWideOneWidensIt) {
  const LegendLayout layout{.font_size = 10, .mark_width = 30};  // 6 px per character
  // Items of 30 + 60 + 10 = 100 px from the margin 10, on a page of 300: two per row.
  const std::vector<LegendItem> items{item("0123456789"), item("0123456789"), item("0123456789")};
  double page_width = 300;
  const std::vector<LegendPlace> places = flowing_legend_places(items, layout, 10, 10, page_width);
  ASSERT_EQ(places.size(), 3u);
  EXPECT_DOUBLE_EQ(places[0].left, 10);
  EXPECT_EQ(places[0].row, 0);
  EXPECT_DOUBLE_EQ(places[1].left, 110);
  EXPECT_EQ(places[1].row, 0);
  EXPECT_DOUBLE_EQ(places[2].left, 10);
  EXPECT_EQ(places[2].row, 1);
  EXPECT_DOUBLE_EQ(page_width, 300);

  // An item wider than the page stays on the first row and widens the page to whole pixels.
  double narrow = 50;
  const std::vector<LegendPlace> wide = flowing_legend_places({item("01234567890.5")}, layout, 10.5, 10, narrow);
  ASSERT_EQ(wide.size(), 1u);
  EXPECT_EQ(wide[0].row, 0);
  EXPECT_DOUBLE_EQ(narrow, 139);  // ceil(10 + (30 + 78 + 10.5) + 10)
}

TEST(LegendTest, PlacesMustMatchTheItems) {
  std::string svg;
  EXPECT_THROW(draw_legend_at(svg, 0, {item("a")}, {}, {}), std::invalid_argument);
  EXPECT_EQ(count_of(svg, "<g"), 0u);
}

}  // namespace
}  // namespace crux
