#include "reports/web_assets.hpp"

#include <algorithm>

#include <gtest/gtest.h>

namespace crux {
namespace {

bool ascii(std::string_view text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 128; });
}

// Both are inlined as they are into the page: they must not close their own element.
TEST(WebAssets, TheBundleAndStyleCanBeInlined) {
  const std::string_view script = replay_script();
  const std::string_view style = report_style();
  EXPECT_GT(script.size(), 100000u) << "three.js is bundled in";
  EXPECT_FALSE(style.empty());
  EXPECT_EQ(script.find("</script"), std::string_view::npos);
  EXPECT_EQ(style.find("</style"), std::string_view::npos);
  EXPECT_TRUE(ascii(script));
  EXPECT_TRUE(ascii(style));
  EXPECT_NE(script.find("crux-replay-data"), std::string_view::npos) << "it reads the page's replay data";
  EXPECT_NE(script.find("crux-performed-data"), std::string_view::npos) << "and a performed climb's";
}

}  // namespace
}  // namespace crux
