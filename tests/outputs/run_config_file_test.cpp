#include "outputs/run_config_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

// A 3 x 2 grid, every grid key given, as crux writes them.
constexpr const char* kRunConfig = R"([experiment]
seed = 7

[grid]
columns = 3
rows = 2
tile_width = 0.3
tile_height = 0.5
right_hand_anchor_column = 2
right_hand_anchor_row = 0
left_hand_anchor_column = 0
left_hand_anchor_row = 1
right_foot_anchor_column = 1
right_foot_anchor_row = 0
left_foot_anchor_column = 0
left_foot_anchor_row = 0

[provenance]
crux_version = "1.0"
)";

// kRunConfig with `from` replaced by `to`.
std::string edited_run_config(const std::string& from, const std::string& to) {
  std::string text = kRunConfig;
  text.replace(text.find(from), from.size(), to);
  return text;
}

// The InputError that reading `text` as a run's config raises.
InputError run_config_error(const std::string& name, const std::string& text) {
  const auto file = testing::write_temporary(name, text);
  try {
    read_run_config(file);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "read " << name << " without an error";
  return InputError("", "");
}

TEST(RunConfigFile, ReadsEveryKeyWithItsProvenance) {
  const ExperimentConfig config = read_run_config(testing::write_temporary("run_config_good.toml", kRunConfig));
  EXPECT_EQ(config.settings.seed, 7u);
  const GridParameters& grid = config.settings.learning.climbing.grid;
  EXPECT_EQ(grid.columns, 3);
  EXPECT_EQ(grid.rows, 2);
  EXPECT_DOUBLE_EQ(grid.tile_width, 0.3);
  EXPECT_EQ(grid.anchors[0], (std::array<int, 2>{2, 0}));
  EXPECT_EQ(grid.anchors[1], (std::array<int, 2>{0, 1}));
  EXPECT_EQ(config.recorded_provenance.at("crux_version"), "1.0");
}

// Folders written before grid.agent_space existed hold the grid's tables.
TEST(RunConfigFile, TheAgentSpaceIsTheGridUnlessTheFileNamesAnother) {
  const ExperimentConfig old = read_run_config(testing::write_temporary("run_config_no_space.toml", kRunConfig));
  EXPECT_EQ(old.settings.learning.climbing.grid.space, AgentSpaceKind::Grid);
  const ExperimentConfig reach = read_run_config(testing::write_temporary(
      "run_config_reach.toml", edited_run_config("[grid]\n", "[grid]\nagent_space = \"reach\"\n")));
  EXPECT_EQ(reach.settings.learning.climbing.grid.space, AgentSpaceKind::Reach);
}

TEST(RunConfigFile, EveryGridKeyMustBeGiven) {
  const InputError e = run_config_error("run_config_no_rows.toml", edited_run_config("rows = 2\n", ""));
  EXPECT_TRUE(e.source().ends_with("run_config_no_rows.toml")) << e.source();
  EXPECT_EQ(e.problem(), "grid.rows is missing (crux writes every grid key)");
}

TEST(RunConfigFile, AValueOfTheWrongTypeNamesItsLine) {
  const InputError e = run_config_error("run_config_type.toml", edited_run_config("columns = 3", "columns = \"3\""));
  EXPECT_TRUE(e.source().ends_with("run_config_type.toml")) << e.source();
  EXPECT_EQ(e.problem(), "line 5: grid.columns must be an integer");
  EXPECT_EQ(
      run_config_error("run_config_inf.toml", edited_run_config("tile_width = 0.3", "tile_width = inf")).problem(),
      "line 7: grid.tile_width must be a finite number");
  EXPECT_EQ(run_config_error("run_config_unknown.toml", edited_run_config("[grid]\n", "[grid]\nsize = 3\n")).problem(),
            "line 5: unknown key grid.size");
}

// The parameter table's rules, the same as for a --config file: the stricter of the two
// readers the grid had (the figures' allowed a million tiles; the agent-state codes
// allow 1023).
TEST(RunConfigFile, AValueOutOfRangeNamesItsLineAndKey) {
  InputError e = run_config_error("run_config_rows.toml", edited_run_config("rows = 2", "rows = 0"));
  EXPECT_TRUE(e.source().ends_with("run_config_rows.toml: line 6: grid.rows")) << e.source();
  EXPECT_EQ(e.problem(), "must be from 1 to 1000");
  e = run_config_error("run_config_tiles.toml", edited_run_config("columns = 3", "columns = 1000"));
  EXPECT_TRUE(e.source().ends_with(": line 5: grid.columns")) << e.source();
  EXPECT_EQ(e.problem(), "the grid has too many tiles for 32-bit agent-state codes");
  e = run_config_error("run_config_anchor.toml",
                       edited_run_config("right_hand_anchor_column = 2", "right_hand_anchor_column = 3"));
  EXPECT_TRUE(e.source().ends_with(": line 9: grid.right_hand_anchor_column")) << e.source();
  EXPECT_EQ(e.problem(), "every grid anchor must be a tile of the grid");
}

}  // namespace
}  // namespace crux
