#include "common/printable.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(Printable, EscapesControlCharactersAndBackslashesOnly) {
  EXPECT_EQ(printable("wall 1 (seed 3)"), "wall 1 (seed 3)");
  EXPECT_EQ(printable("a\nb"), "a\\x0ab");
  EXPECT_EQ(printable("\x1b[31mred"), "\\x1b[31mred");
  EXPECT_EQ(printable("back\\slash\x7f"), "back\\\\slash\\x7f");
  EXPECT_EQ(printable("d\xc3\xa9vers"), "d\xc3\xa9vers") << "UTF-8 text stays";
}

}  // namespace
}  // namespace crux
