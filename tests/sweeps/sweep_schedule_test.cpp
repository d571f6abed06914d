#include "sweeps/sweep_schedule.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace crux {
namespace {

std::vector<SweepTask> tasks_with(const std::vector<int>& depends_on) {
  std::vector<SweepTask> tasks(depends_on.size());
  for (std::size_t t = 0; t < tasks.size(); ++t) tasks[t].depends_on = depends_on[t];
  return tasks;
}

TEST(SweepSchedule, HandsOutTheLowestReadyTaskAndHoldsDependentsBack) {
  // Task 2 waits for 0; task 3 for 1.
  const auto tasks = tasks_with({-1, -1, 0, 1});
  SweepSchedule schedule(tasks, std::vector<bool>(4, false));
  EXPECT_EQ(schedule.next(), 0u);
  EXPECT_EQ(schedule.next(), 1u);
  EXPECT_EQ(schedule.next(), std::nullopt) << "2 and 3 wait for running tasks";
  schedule.finish(1);
  EXPECT_EQ(schedule.next(), 3u);
  schedule.finish(0);
  EXPECT_EQ(schedule.next(), 2u);
  EXPECT_FALSE(schedule.done());
  schedule.finish(3);
  schedule.finish(2);
  EXPECT_TRUE(schedule.done());
  EXPECT_EQ(schedule.finished_count(), 4u);
  EXPECT_THROW(schedule.finish(2), std::logic_error);
}

TEST(SweepSchedule, AResumedScheduleSkipsFinishedTasks) {
  const auto tasks = tasks_with({-1, -1, 0, 1});
  SweepSchedule schedule(tasks, {true, false, false, false});
  EXPECT_EQ(schedule.finished_count(), 1u);
  EXPECT_EQ(schedule.next(), 1u);
  EXPECT_EQ(schedule.next(), 2u) << "its dependency finished before";
  EXPECT_EQ(schedule.next(), std::nullopt);
  EXPECT_THROW(SweepSchedule(tasks, {true}), std::invalid_argument);
}

}  // namespace
}  // namespace crux
