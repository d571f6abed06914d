#include "jobs/perform_job.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "common/input_error.hpp"
#include "support/jug_ladder.hpp"
#include "support/output_text.hpp"
#include "wall/wall_file.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

// The jug ladder climbed by its one move, as a wall file, under the static model.
PerformJob ladder_job(std::optional<fs::path> output) {
  static const fs::path wall_file = [] {
    const fs::path file = testing::temporary_path("jug_ladder.json");
    testing::JugLadder ladder;
    ladder.finish_after_one_move();
    save_wall(file.string(), ladder.wall);
    return file;
  }();
  PerformJob job;
  job.config.wall_file = wall_file.string();
  job.config.settings.learning.climbing.physics.model = PhysicsModel::Static;
  finalize_config(job.config);
  job.output = std::move(output);
  return job;
}

TEST(PerformJob, WritesTheClimbsFolderTheSameBytesEachTime) {
  const fs::path first = testing::temporary_path("perform-first");
  const fs::path second = testing::temporary_path("perform-second");
  const PerformJobOutcome outcome = run_perform_job(ladder_job(first), {"a test", {}, {}, {}});
  run_perform_job(ladder_job(second), {"a test", {}, {}, {}});
  ASSERT_TRUE(outcome.performed.plan.found);
  EXPECT_TRUE(outcome.performed.performed()) << outcome.record.dump(2);
  for (const char* file : {"config.toml", "wall.json", "perform.json", "trajectory.csv", "climber.xml"}) {
    ASSERT_TRUE(fs::exists(first / file)) << file;
    EXPECT_EQ(testing::read_output_text(first / file), testing::read_output_text(second / file)) << file;
  }
  EXPECT_FALSE(fs::exists(first / "INCOMPLETE"));
  EXPECT_EQ(testing::read_output_text(first / "perform.json"), outcome.record.dump(2) + "\n");
  EXPECT_NE(testing::read_output_text(first / "config.toml").find("[perform]"), std::string::npos);
}

// Hands whose grip is 1 N cannot hold the start: refused before the folder is touched.
TEST(PerformJob, AWallWhoseStartDoesNotHoldIsRefusedAndNothingIsWritten) {
  const fs::path folder = testing::temporary_path("perform-refused");
  PerformJob job = ladder_job(folder);
  job.config.settings.learning.climbing.physics.grip = 1.0;
  EXPECT_THROW(run_perform_job(std::move(job), {"a test", {}, {}, {}}), InputError);
  EXPECT_FALSE(fs::exists(folder));
}

}  // namespace
}  // namespace crux
