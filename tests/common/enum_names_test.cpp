#include "common/enum_names.hpp"

#include <gtest/gtest.h>

namespace crux {

// An enum declared inline, as each named enum of crux declares its names beside itself.
enum class Colour { Red, DarkGreen, Blue };
template <>
struct EnumNames<Colour> {
  static constexpr std::array<EnumName<Colour>, 3> entries{
      {{Colour::Red, "red", "r"}, {Colour::DarkGreen, "dark-green"}, {Colour::Blue, "blue"}}};
};

namespace {

TEST(EnumNames, EveryValueHasItsNameAndParsesBack) {
  for (const Colour colour : {Colour::Red, Colour::DarkGreen, Colour::Blue}) {
    EXPECT_EQ(parse_enum<Colour>(enum_name(colour)), colour);
  }
  EXPECT_STREQ(enum_name(Colour::DarkGreen), "dark-green");
}

TEST(EnumNames, AnAliasParsesButIsNeverWritten) {
  EXPECT_EQ(parse_enum<Colour>("r"), Colour::Red);
  EXPECT_STREQ(enum_name(Colour::Red), "red");
  EXPECT_FALSE(parse_enum<Colour>("b")) << "blue has no alias";
}

TEST(EnumNames, UnknownTextAndCaseAreRefused) {
  EXPECT_FALSE(parse_enum<Colour>(""));
  EXPECT_FALSE(parse_enum<Colour>("Red"));
  EXPECT_FALSE(parse_enum<Colour>("green"));
  EXPECT_STREQ(enum_name(static_cast<Colour>(7)), "?");
}

TEST(EnumNames, ChoicesReadAsAList) { EXPECT_EQ(enum_choices<Colour>(), "red, dark-green or blue"); }

}  // namespace
}  // namespace crux
