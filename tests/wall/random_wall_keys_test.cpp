#include "wall/random_wall_keys.hpp"

#include <gtest/gtest.h>

#include "support/key_declaration.hpp"

namespace crux {
namespace {

TEST(RandomWallKeys, DeclaresTheGeneratorsParametersInTheWallSection) {
  RandomWallParameters walls;
  expect_key_declaration(walls, [](auto& keys, auto& p) { random_wall_keys(keys, p); }, {"wall"});
}

TEST(RandomWallKeys, AnInclineStopsShortOfHorizontal) {
  RandomWallParameters walls;
  std::vector<ConfigField> keys;
  random_wall_keys(keys, walls);
  const Bounds& incline = declared_field(keys, "wall.incline").bounds;
  EXPECT_TRUE(incline.contains(89.9));
  EXPECT_FALSE(incline.contains(90));
  EXPECT_FALSE(incline.contains(-90));
  EXPECT_EQ(declared_field(keys, "wall.incline").unit, "degrees");
}

}  // namespace
}  // namespace crux
