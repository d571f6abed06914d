#include "experiments/learning_parameters.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

// What each learning command takes: a run its wall and seed, transfer its Q_grid too,
// the paper's experiment draws its own walls; none takes another command's keys.
TEST(LearningParameters, EachCommandTakesItsOwnKeys) {
  EXPECT_TRUE(kTrainParameters.accepts("wall.file"));
  EXPECT_TRUE(kTrainParameters.accepts("learning.epsilon"));
  EXPECT_FALSE(kTrainParameters.accepts("experiment.q_grid"));
  EXPECT_FALSE(kTrainParameters.accepts("experiment.walls"));
  EXPECT_TRUE(kTransferParameters.accepts("experiment.q_grid"));
  EXPECT_FALSE(kTransferParameters.accepts("wall.name"));
  EXPECT_TRUE(kPaperParameters.accepts("experiment.walls"));
  EXPECT_FALSE(kPaperParameters.accepts("wall.file"));
  EXPECT_FALSE(kPaperParameters.accepts("experiment.q_grid"));
  for (const ParameterSet* set : {&kTrainParameters, &kTransferParameters, &kPaperParameters}) {
    EXPECT_FALSE(set->accepts("compare.queries")) << "ik-compare's keys belong to ik-compare";
    EXPECT_FALSE(set->accepts("wall.count")) << "filter-stats' key";
  }
}

}  // namespace
}  // namespace crux
