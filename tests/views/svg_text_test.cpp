#include "views/svg_text.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(SvgTextTest, EscapesXmlSpecialCharacters) {
  EXPECT_EQ(xml_escaped("a<b & \"c\" > 'd'"), "a&lt;b &amp; &quot;c&quot; &gt; &apos;d&apos;");
  EXPECT_EQ(xml_escaped("plain text"), "plain text");
}

TEST(SvgTextTest, ReplacesControlCharactersThatXmlForbids) {
  EXPECT_EQ(xml_escaped(std::string("a\x01z")), "a\xEF\xBF\xBDz");
  EXPECT_EQ(xml_escaped("tab\tand\nline"), "tab\tand\nline");
}

TEST(SvgTextTest, WidthCountsCodePointsNotBytes) {
  EXPECT_DOUBLE_EQ(estimated_text_width("abcd", 10), 24.0);
  // "95 %" with a UTF-8 non-breaking space (2 bytes) is 4 characters wide.
  EXPECT_DOUBLE_EQ(estimated_text_width("95\xC2\xA0%", 10), 24.0);
  EXPECT_DOUBLE_EQ(estimated_text_width("", 12), 0.0);
}

// Half a metre between metre lines while they stay 30 pixels apart, doubled otherwise.
TEST(SvgTextTest, MetreLinesStayThirtyPixelsApart) {
  EXPECT_DOUBLE_EQ(metre_tick_spacing(60), 0.5);   // 30 px apart: the finest spacing
  EXPECT_DOUBLE_EQ(metre_tick_spacing(59), 1.0);   // 29.5 px: doubled once
  EXPECT_DOUBLE_EQ(metre_tick_spacing(30), 1.0);
  EXPECT_DOUBLE_EQ(metre_tick_spacing(29), 2.0);
  EXPECT_DOUBLE_EQ(metre_tick_spacing(1), 32.0);   // 16 px at 16 m, 32 px at 32 m
}

}  // namespace
}  // namespace crux
