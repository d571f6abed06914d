#include "sweeps/sweep_definition.hpp"

#include <gtest/gtest.h>

#include "jobs/command_keys.hpp"

namespace crux {
namespace {

const std::string kSweepFile =
    "[experiment]\nwalls = 2\nthreads = 2\nplan = false\n[learning]\nepsilon = [0.1, 0.25]\n"
    "planner = [\"uniform\", \"prioritized\"]\n";

ExperimentConfig resolved(const ListChoice& choice) {
  ExperimentConfig config;
  apply_config_text(kSweepFile, "sweep.toml", config, kSweepKeys, "sweep", choice);
  finalize_config(config);
  return config;
}

TEST(SweepDefinition, CellsTakeEveryCombinationAndTheSweepFileKeepsTheLists) {
  const SweepGrid grid{listed_keys(kSweepFile, "sweep.toml", kSweepKeys)};
  const SweepDefinition definition = define_sweep(grid, resolved);
  ASSERT_EQ(definition.plan.cells.size(), 4u);
  EXPECT_EQ(definition.plan.keys, (std::vector<std::string>{"learning.epsilon", "learning.planner"}));
  EXPECT_EQ(definition.plan.cells[1].values, (std::vector<std::string>{"0.1", "prioritized"}));
  EXPECT_DOUBLE_EQ(definition.plan.cells[2].config.settings.learning.dyna.epsilon, 0.25);
  EXPECT_EQ(definition.plan.cells[3].config.settings.learning.dyna.planner, Planner::Prioritized);
  const std::string& text = definition.sweep_toml;
  EXPECT_NE(text.find("epsilon = [0.1, 0.25]  #"), std::string::npos) << text;
  EXPECT_NE(text.find("planner = [\"uniform\", \"prioritized\"]  #"), std::string::npos);
  EXPECT_EQ(text.find("threads ="), std::string::npos) << "results do not depend on the threads";
  EXPECT_NE(text.find("[provenance]"), std::string::npos);
  // The written file defines the same sweep.
  const SweepGrid again{listed_keys(text, "written.toml", kSweepKeys)};
  EXPECT_EQ(again.cells(), 4u);
}

}  // namespace
}  // namespace crux
