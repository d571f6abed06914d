#include "experiments/climb_stances.hpp"

#include <gtest/gtest.h>

#include "outputs/run_folder.hpp"
#include "support/test_models.hpp"
#include "support/trained_run.hpp"

namespace crux {
namespace {

// The kinematic model checks no stance: there is nothing to show.
TEST(ClimbStances, TheKinematicModelHasNone) {
  const RunFolder folder = testing::read_trained_run();
  EXPECT_FALSE(climb_stances(testing::human_model(), folder.wall, folder.last, PhysicsParameters{}).has_value());
}

// Under the static model every posture of the climb has its stance: its loads on its four
// holds agree with the effort asked on the same holds, and letting a limb go never makes a
// stance easier to hold (the three holds' forces are a subset of the four's).
TEST(ClimbStances, EveryPostureHasItsStanceAndLettingGoIsNeverEasier) {
  const RunFolder folder = testing::read_trained_run();
  PhysicsParameters physics;
  physics.model = PhysicsModel::Static;
  const std::optional<ClimbStances> stances = climb_stances(testing::human_model(), folder.wall, folder.last, physics);
  ASSERT_TRUE(stances.has_value());
  const std::size_t postures = folder.last.postures.size();
  ASSERT_GT(postures, 1u);
  ASSERT_EQ(stances->loads.size(), postures);
  ASSERT_EQ(stances->effort_on_four_holds.size(), postures);
  ASSERT_EQ(stances->effort_on_three_holds.size(), postures);
  for (std::size_t k = 0; k < postures; ++k) {
    const double four = stances->effort_on_four_holds[k], three = stances->effort_on_three_holds[k];
    if (std::isinf(four)) {
      EXPECT_FALSE(stances->loads[k].balanced) << "stance " << k;
    } else {
      EXPECT_NEAR(stances->loads[k].effort, four, 1e-6 * std::max(1.0, four)) << "stance " << k;
    }
    EXPECT_GE(three, four - 1e-6 * std::max(1.0, four)) << "stance " << k;
    int held = 0;
    for (const bool h : stances->loads[k].held) held += h;
    EXPECT_EQ(held, kLimbCount) << "stance " << k << " is on its four holds";
  }
}

}  // namespace
}  // namespace crux
