#include "jobs/command_keys.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

// What each learning command takes: a run its wall and seed, transfer its Q_grid too,
// the paper's experiment draws its own walls; none takes another command's keys.
TEST(CommandKeys, EachCommandTakesItsOwnKeys) {
  EXPECT_TRUE(kTrainKeys.accepts("wall.file"));
  EXPECT_TRUE(kTrainKeys.accepts("learning.epsilon"));
  EXPECT_FALSE(kTrainKeys.accepts("experiment.q_grid"));
  EXPECT_FALSE(kTrainKeys.accepts("experiment.walls"));
  EXPECT_TRUE(kTransferKeys.accepts("experiment.q_grid"));
  EXPECT_FALSE(kTransferKeys.accepts("wall.name"));
  EXPECT_TRUE(kPaperKeys.accepts("experiment.walls"));
  EXPECT_FALSE(kPaperKeys.accepts("wall.file"));
  EXPECT_FALSE(kPaperKeys.accepts("experiment.q_grid"));
  for (const ParameterSet* set : {&kTrainKeys, &kTransferKeys, &kPaperKeys}) {
    EXPECT_FALSE(set->accepts("compare.queries")) << "ik-compare's keys belong to ik-compare";
    EXPECT_FALSE(set->accepts("wall.count")) << "filter-stats' key";
  }
}

}  // namespace
}  // namespace crux
