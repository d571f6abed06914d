#include "common/xml_escaped.hpp"

#include <gtest/gtest.h>

#include <string>

namespace crux {
namespace {

TEST(XmlEscaped, EscapesXmlSpecialCharacters) {
  EXPECT_EQ(xml_escaped("a<b & \"c\" > 'd'"), "a&lt;b &amp; &quot;c&quot; &gt; &apos;d&apos;");
  EXPECT_EQ(xml_escaped("plain text"), "plain text");
}

TEST(XmlEscaped, ReplacesControlCharactersThatXmlForbids) {
  EXPECT_EQ(xml_escaped(std::string("a\x01z")), "a\xEF\xBF\xBDz");
  EXPECT_EQ(xml_escaped("tab\tand\nline"), "tab\tand\nline");
}

}  // namespace
}  // namespace crux
