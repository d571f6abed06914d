#include "sweeps/sweep_definition.hpp"

#include <gtest/gtest.h>

#include <string>

#include "common/input_error.hpp"
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
  const SweepGrid grid{listed_keys(ConfigDocument(kSweepFile, "sweep.toml"), kSweepKeys)};
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
  const SweepGrid again{listed_keys(ConfigDocument(text, "written.toml"), kSweepKeys)};
  EXPECT_EQ(again.cells(), 4u);
}

// Issue 25: every cell was built, each re-reading the sweep file, before any limit was
// checked. Expanding a sweep builds each cell once from one parse of its file, and a
// sweep over the cell bound builds none.
TEST(SweepDefinition, ExpandingASweepBuildsEachCellOnceFromOneParse) {
  for (const std::size_t seeds : {std::size_t{3}, std::size_t{300}}) {
    std::string text = "[experiment]\nwalls = 1\nplan = false\nseed = [";
    for (std::size_t s = 0; s < seeds; ++s) text += (s > 0 ? ", " : "") + std::to_string(s + 1);
    text += "]\n[learning]\nepsilon = [0.1, 0.25]\n";
    const std::size_t parses_before = ConfigDocument::parses();
    const ConfigDocument document(text, "sweep.toml");
    std::size_t built = 0;
    const SweepGrid grid{listed_keys(document, kSweepKeys), "sweep.toml"};
    const SweepDefinition definition = define_sweep(grid, [&](const ListChoice& choice) {
      ++built;
      ExperimentConfig config;
      apply_config_document(document, config, kSweepKeys, "sweep", choice);
      finalize_config(config);
      return config;
    });
    EXPECT_EQ(definition.plan.cells.size(), 2 * seeds);
    EXPECT_EQ(built, 2 * seeds);
    EXPECT_EQ(ConfigDocument::parses() - parses_before, 1u) << seeds << " seeds";
  }
}

TEST(SweepDefinition, ASweepOverTheCellBoundBuildsNoCell) {
  std::size_t built = 0;
  const SweepGrid grid{{{"experiment.seed", 1000000}, {"learning.epsilon", 2}}, "sweep.toml"};
  EXPECT_THROW(define_sweep(grid,
                            [&](const ListChoice&) {
                              ++built;
                              return ExperimentConfig{};
                            }),
               InputError);
  EXPECT_EQ(built, 0u);
}

// Issue 25: a sweep under the cell bound was built whole before its task count was
// checked. Building stops at the first cell that takes the count past the bound: here
// each cell has 3 x 100 runs and the largest wall group 2 x 100 walls, so the third cell
// (900 + 200 tasks) passes 1000, and the other 997 cells are never built.
TEST(SweepDefinition, ASweepOverTheTaskBoundStopsBuildingAtTheCellThatPassesIt) {
  std::string text = "[experiment]\nwalls = 100\nplan = false\nseed = [";
  for (int seed = 1; seed <= 500; ++seed) text += (seed > 1 ? ", " : "") + std::to_string(seed);
  text += "]\n[learning]\nepsilon = [0.1, 0.25]\n";
  const ConfigDocument document(text, "sweep.toml");
  std::size_t built = 0;
  const SweepGrid grid{listed_keys(document, kSweepKeys), "sweep.toml"};
  ASSERT_EQ(grid.cells(), 1000u);
  try {
    define_sweep(
        grid,
        [&](const ListChoice& choice) {
          ++built;
          ExperimentConfig config;
          apply_config_document(document, config, kSweepKeys, "sweep", choice);
          finalize_config(config);
          return config;
        },
        1000);
    ADD_FAILURE() << "a sweep of 1000 cells of 500 tasks each was accepted";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "experiment.walls: the sweep has 1100 walls and runs; at most 1000 are allowed");
  }
  EXPECT_EQ(built, 3u);
}

}  // namespace
}  // namespace crux
