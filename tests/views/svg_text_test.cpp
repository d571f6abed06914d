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

}  // namespace
}  // namespace crux
