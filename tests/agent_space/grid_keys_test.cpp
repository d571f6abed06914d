#include "agent_space/grid_keys.hpp"

#include <gtest/gtest.h>

#include "support/key_declaration.hpp"

namespace crux {
namespace {

TEST(GridKeys, DeclaresTheAgentSpacesParametersWithEachLimbsAnchor) {
  GridParameters grid;
  expect_key_declaration(grid, [](auto& keys, auto& p) { grid_keys(keys, p); }, {"grid"});
  std::vector<ConfigField> keys;
  grid_keys(keys, grid);
  *std::get<int*>(declared_field(keys, "grid.left_foot_anchor_row").target) = 7;
  EXPECT_EQ(grid.anchors[3][1], 7);
}

}  // namespace
}  // namespace crux
