#include "experiments/run_inputs.hpp"

#include <gtest/gtest.h>

#include "agent_space/agent_descriptor.hpp"
#include "common/input_error.hpp"
#include "learning/q_table_file.hpp"
#include "support/test_models.hpp"
#include "wall/wall_file.hpp"

namespace crux {
namespace {

TEST(RunInputs, TheWallIsTheFileOrTheSeedsRandomWall) {
  ExperimentConfig config;
  EXPECT_THROW(load_configured_wall(config), InputError) << "neither a file nor a seed";
  config.wall_seed = 9;
  config.settings.walls.columns = 6;
  const Wall random = load_configured_wall(config);
  EXPECT_EQ(random.hold_count(), generate_random_wall(9, config.settings.walls).hold_count());
  EXPECT_EQ(random.holds.back().position, generate_random_wall(9, config.settings.walls).holds.back().position);
  const auto path = testing::temporary_path("run_inputs_wall.json");
  save_wall(path.string(), random);
  ExperimentConfig from_file;
  from_file.wall_file = path.string();
  EXPECT_EQ(load_configured_wall(from_file).holds.back().position, random.holds.back().position);
}

TEST(RunInputs, AQGridOfAnotherGridIsRefusedNamingTheFile) {
  GridParameters grid;  // 5 x 7
  QTable q(grid.tile_count());
  q.set_value(agent_state_count(grid) - 1, 0, 1.0);
  const auto fits = testing::temporary_path("q_fits.bin");
  save_q_table(fits.string(), q, describe_grid(grid));
  EXPECT_NO_THROW(load_q_grid(fits.string(), grid));
  q.set_value(agent_state_count(grid), 0, 1.0);  // the first code beyond the grid
  const auto beyond = testing::temporary_path("q_beyond.bin");
  save_q_table(beyond.string(), q, describe_grid(grid));
  try {
    load_q_grid(beyond.string(), grid);
    FAIL() << "accepted a state code beyond the grid";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), beyond.string());
    EXPECT_NE(std::string(e.what()).find("does not exist on a 5 x 7 grid"), std::string::npos) << e.what();
  }
  GridParameters other = grid;
  other.rows = 3;  // another tile count: another action count
  EXPECT_THROW(load_q_grid(fits.string(), other), InputError);
}

// Same tile count, so the same action count; the recorded grid tells them apart.
TEST(RunInputs, AQGridLearntOnA7By5GridIsRefusedOnA5By7Run) {
  GridParameters wide;
  wide.columns = 7;
  wide.rows = 5;
  wide.anchors = {{{1, 3}, {3, 3}, {1, 1}, {3, 1}}};
  const auto path = testing::temporary_path("q_wide.bin");
  save_q_table(path.string(), QTable(wide.tile_count()), describe_grid(wide));
  EXPECT_NO_THROW(load_q_grid(path.string(), wide));
  try {
    load_q_grid(path.string(), GridParameters{});
    FAIL() << "a 7 x 5 table loaded into a 5 x 7 run";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), path.string());
    EXPECT_NE(std::string(e.what()).find("learnt on a 7 x 5 moving grid"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("this run uses a 5 x 7 moving grid"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace crux

namespace crux {
namespace {

TEST(RunInputs, AQGridInMemoryIsCheckedLikeAFile) {
  const GridParameters grid;
  QTable fits(grid.tile_count());
  fits.set_value(agent_state_count(grid) - 1, 0, 1.0);
  EXPECT_NO_THROW(check_q_grid(fits, grid, "table"));
  try {
    check_q_grid(QTable(grid.tile_count() - 1), grid, "table");
    FAIL() << "a table of 34 actions passed for a 35-tile grid";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "table: has 34 actions, but the grid has 35 tiles");
  }
  try {
    check_q_grid(QTable(1), grid, "table");
    FAIL() << "a table of 1 action passed for a 35-tile grid";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "table: has 1 action, but the grid has 35 tiles");
  }
  QTable foreign(grid.tile_count());
  foreign.set_value(agent_state_count(grid), 0, 1.0);
  EXPECT_THROW(check_q_grid(foreign, grid, "table"), InputError);
}

}  // namespace
}  // namespace crux
