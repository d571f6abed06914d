#include "views/svg_document.hpp"

#include <gtest/gtest.h>

#include <string>

#include "support/svg_check.hpp"

namespace crux {
namespace {

using testing::check_well_formed;

TEST(SvgDocumentTest, WidthCountsCodePointsNotBytes) {
  EXPECT_DOUBLE_EQ(estimated_text_width("abcd", 10), 24.0);
  // "95 %" with a UTF-8 non-breaking space (2 bytes) is 4 characters wide.
  EXPECT_DOUBLE_EQ(estimated_text_width("95\xC2\xA0%", 10), 24.0);
  EXPECT_DOUBLE_EQ(estimated_text_width("", 12), 0.0);
}

TEST(SvgDocumentTest, DocumentRoundsItsSizeUpAndEscapesItsTitle) {
  const std::string svg = svg_document(400.2, 199.5, "wall <1> & co", "<g/>\n");
  EXPECT_EQ(check_well_formed(svg), "");
  EXPECT_EQ(
      svg.rfind(
          "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
          "version=\"1.1\" width=\"401\" height=\"200\" viewBox=\"0 0 401 200\"",
          0),
      0u);
  EXPECT_NE(
      svg.find("<title>wall &lt;1&gt; &amp; co</title>\n<rect width=\"401\" height=\"200\" fill=\"white\"/>\n<g/>\n"
               "</svg>\n"),
      std::string::npos);
  EXPECT_EQ(svg.find("xmlns:xlink"), std::string::npos);
}

TEST(SvgDocumentTest, DeclaresXlinkOnlyWhenAsked) {
  const std::string svg = svg_document(10, 10, "t", "", XlinkNamespace::Declared);
  EXPECT_EQ(check_well_formed(svg), "");
  EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
                     "version=\"1.1\""),
            std::string::npos);
}

TEST(SvgDocumentTest, LinesWriteTheirCoordinatesWithTwoDecimals) {
  std::string svg;
  draw_vertical_line(svg, 1, 2, 3.456);
  draw_horizontal_line(svg, 1, 2, 3.456);
  EXPECT_EQ(svg,
            "<line x1=\"1.00\" y1=\"2.00\" x2=\"1.00\" y2=\"3.46\"/>\n"
            "<line x1=\"1.00\" y1=\"3.46\" x2=\"2.00\" y2=\"3.46\"/>\n");
}

TEST(SvgDocumentTest, StrokedLinesCarryTheirClassWidthAndDash) {
  std::string svg;
  draw_line(svg, 0, 1, 2, 3, {"#123456", 1.2, "6 4"}, "finish");
  draw_line(svg, 0, 1, 2, 3, {"#123456", 2, ""});
  EXPECT_EQ(svg,
            "<line class=\"finish\" x1=\"0.00\" y1=\"1.00\" x2=\"2.00\" y2=\"3.00\" stroke=\"#123456\" "
            "stroke-width=\"1.2\" stroke-dasharray=\"6 4\"/>\n"
            "<line x1=\"0.00\" y1=\"1.00\" x2=\"2.00\" y2=\"3.00\" stroke=\"#123456\" stroke-width=\"2\"/>\n");
}

TEST(SvgDocumentTest, TextIsEscapedAndStyledOnlyWhereAsked) {
  std::string styled;
  draw_text(styled, 5, 6, "a < b",
            {.size = 16, .anchor = "middle", .colour = "#111111", .bold = true, .rotation = -90});
  EXPECT_EQ(styled,
            "<text x=\"5.00\" y=\"6.00\" font-size=\"16\" fill=\"#111111\" text-anchor=\"middle\" font-weight=\"bold\" "
            "transform=\"rotate(-90.0 5.00 6.00)\">a &lt; b</text>\n");
  std::string plain;
  draw_plain_text(plain, 5, 6, "0.5");
  draw_plain_text(plain, 5, 6, "x & y", "end");
  EXPECT_EQ(plain,
            "<text x=\"5.00\" y=\"6.00\">0.5</text>\n"
            "<text x=\"5.00\" y=\"6.00\" text-anchor=\"end\">x &amp; y</text>\n");
}

}  // namespace
}  // namespace crux
