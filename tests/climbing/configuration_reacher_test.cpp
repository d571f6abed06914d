#include "climbing/configuration_reacher.hpp"

#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

// crux wall's start check (solve_start) and the learning's (reach_start) are one test:
// the same verdict and the same posture, for any settings.
TEST(ConfigurationReacher, StartIsSolveStartAnsweredThroughTheCache) {
  const BodyModel& model = testing::human_model();
  ReachabilityParameters strict;
  strict.ik.tolerances.grasp_radius = 0.001;
  strict.ik.fast.max_iterations = 3;
  ReachabilityParameters paper;
  paper.ik.solver = IkSolverKind::Paper;
  int reached = 0, refused = 0;
  for (const ReachabilityParameters& parameters : {ReachabilityParameters{}, strict, paper}) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const Wall wall = generate_random_wall(seed);
      BodyData data(model);
      const IkResult direct = solve_start(model, data, wall, parameters);
      ConfigurationReacher reacher(model, wall, parameters);
      const Posture* start = reacher.reach_start();
      ASSERT_EQ(start != nullptr, direct.reached) << "seed " << seed;
      if (start != nullptr) {
        EXPECT_EQ(*start, direct.posture) << "seed " << seed;
        EXPECT_EQ(&reacher.require_start("wall.json"), start) << "seed " << seed;
        ++reached;
      } else {
        try {
          reacher.require_start("wall.json");
          ADD_FAILURE() << "seed " << seed << ": an unreachable start is an input error";
        } catch (const InputError& error) {
          EXPECT_STREQ(error.what(), "wall.json: the start configuration is not reachable") << "seed " << seed;
        }
        ++refused;
      }
      reacher.reach_start();
      EXPECT_EQ(reacher.solves(), 1u) << "the second start check is a cache hit";
    }
  }
  EXPECT_GT(reached, 0);
  EXPECT_GT(refused, 0) << "the strict settings refuse some starts";
}

}  // namespace
}  // namespace crux
