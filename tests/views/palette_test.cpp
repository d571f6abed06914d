#include "views/palette.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string>
#include <string_view>

namespace crux {
namespace {

bool is_hex_colour(std::string_view colour) {
  if (colour.size() != 7 || colour[0] != '#') return false;
  for (const char c : colour.substr(1)) {
    if (!std::isxdigit(static_cast<unsigned char>(c)) || std::isupper(static_cast<unsigned char>(c))) return false;
  }
  return true;
}

TEST(PaletteTest, ColoursAreLowerCaseHexAsTheFiguresWriteThem) {
  for (const char* colour :
       {kOkabeItoOrange, kOkabeItoBlue, kOkabeItoBluishGreen, kOkabeItoVermillion, kOkabeItoReddishPurple, kTitleColour,
        kTextColour, kDarkGrey, kSubtitleColour, kPlotFrameColour, kViewFrameColour, kPlotGridLineColour,
        kWallMetreLineColour, kBodyMetreLineColour, kAnchorColour}) {
    EXPECT_TRUE(is_hex_colour(colour)) << colour;
  }
  EXPECT_TRUE(is_hex_colour(kFinishStroke.colour));
}

// Okabe and Ito's values, which colour-blind readers tell apart.
TEST(PaletteTest, OkabeItoColoursAreTheirPublishedValues) {
  EXPECT_STREQ(kOkabeItoOrange, "#e69f00");
  EXPECT_STREQ(kOkabeItoBlue, "#0072b2");
  EXPECT_STREQ(kOkabeItoBluishGreen, "#009e73");
  EXPECT_STREQ(kOkabeItoVermillion, "#d55e00");
  EXPECT_STREQ(kOkabeItoReddishPurple, "#cc79a7");
}

TEST(PaletteTest, EachLimbHasItsOwnCodeNameAndColourInLimbOrder) {
  std::set<std::string> codes, names, colours;
  for (const LimbStyle& style : kLimbStyles) {
    codes.insert(style.code);
    names.insert(style.name);
    colours.insert(style.colour);
  }
  EXPECT_EQ(codes.size(), static_cast<std::size_t>(kLimbCount));
  EXPECT_EQ(names.size(), static_cast<std::size_t>(kLimbCount));
  EXPECT_EQ(colours.size(), static_cast<std::size_t>(kLimbCount));
  EXPECT_STREQ(kLimbStyles[static_cast<int>(Limb::RightHand)].code, "RH");
  EXPECT_STREQ(kLimbStyles[static_cast<int>(Limb::LeftFoot)].name, "left foot");
  EXPECT_EQ(colours.count(kAnchorColour), 0u);  // the anchor is told apart from every limb
}

TEST(PaletteTest, TheFinishLineIsDashed) {
  EXPECT_FALSE(kFinishStroke.dash.empty());
  EXPECT_GT(kFinishStroke.width, 0);
}

}  // namespace
}  // namespace crux
