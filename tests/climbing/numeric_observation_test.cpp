#include "climbing/numeric_observation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "body/kinematics.hpp"
#include "climbing/climbing_mdp.hpp"
#include "common/input_error.hpp"
#include "support/climb_start.hpp"
#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

constexpr int kSlots = 32;
constexpr double kSpan = 2.8;

struct ObservationStorage {
  std::vector<float> free_limb = std::vector<float>(4), held = std::vector<float>(12),
                     candidates = std::vector<float>(3 * kSlots), mask = std::vector<float>(kSlots),
                     posture = std::vector<float>(kConfigurationDof), com = std::vector<float>(3),
                     to_finish = std::vector<float>(1);
  std::vector<float> reach = std::vector<float>(kReachFeatures * kSlots), failed = std::vector<float>(kSlots);
  NumericObservationRows rows() {
    return {free_limb.data(), held.data(), candidates.data(), mask.data(),
            posture.data(),   com.data(),  to_finish.data()};
  }
  NumericObservationRows reach_rows() {
    NumericObservationRows out = rows();
    out.candidate_reach = reach.data();
    out.candidate_failed = failed.data();
    return out;
  }
};

using StartState = testing::ClimbStart;

float relative(double value, double origin) { return static_cast<float>(value - origin); }

TEST(NumericObservation, PlacesTheStateRelativeToTheFreeLimbsGraspPoint) {
  StartState s;
  ObservationStorage out;
  BodyData data(s.model);
  write_numeric_observation(s.model, data, s.input(s.wall, kSpan), kSlots, out.rows());

  EXPECT_EQ(out.free_limb, (std::vector<float>{1, 0, 0, 0}));  // the start frees the right hand
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const int hold = s.mdp.configuration().holds[limb];
    for (int k = 0; k < 3; ++k) {
      const float expected = hold == kFree ? 0.0F : relative(s.wall.holds[hold].position[k], s.grasp[k]);
      EXPECT_EQ(out.held[3 * limb + k], expected) << "limb " << limb;
    }
  }
  const auto count = static_cast<int>(s.candidates.size());
  ASSERT_GT(count, 0);
  for (int slot = 0; slot < kSlots; ++slot) {
    EXPECT_EQ(out.mask[slot], slot < count ? 1.0F : 0.0F);
    for (int k = 0; k < 3; ++k) {
      const float expected = slot < count ? relative(s.wall.holds[s.candidates[slot]].position[k], s.grasp[k]) : 0.0F;
      EXPECT_EQ(out.candidates[3 * slot + k], expected) << "slot " << slot;
    }
  }
  for (int i = 0; i < kConfigurationDof; ++i) {
    const float expected = i < 3 ? relative(s.mdp.posture()[i], s.grasp[i]) : static_cast<float>(s.mdp.posture()[i]);
    EXPECT_EQ(out.posture[i], expected) << "coordinate " << i;
  }
  for (int k = 0; k < 3; ++k) EXPECT_EQ(out.com[k], relative(s.centre_of_mass[k], s.grasp[k]));
  EXPECT_EQ(out.to_finish[0], relative(s.wall.finish_height, s.centre_of_mass.z()));
}

TEST(NumericObservation, ClipsTheHeightLeftToTwiceTheSpan) {
  StartState s;
  ObservationStorage out;
  BodyData data(s.model);
  Wall high = s.wall;
  high.finish_height = 100.0;
  write_numeric_observation(s.model, data, s.input(high, kSpan), kSlots, out.rows());
  EXPECT_EQ(out.to_finish[0], static_cast<float>(2 * kSpan));
  Wall low = s.wall;
  low.finish_height = -100.0;
  write_numeric_observation(s.model, data, s.input(low, kSpan), kSlots, out.rows());
  EXPECT_EQ(out.to_finish[0], static_cast<float>(-2 * kSpan));
}

TEST(NumericObservation, RefusesMoreCandidatesThanSlotsNamingMaxCandidates) {
  StartState s;
  ObservationStorage out;
  BodyData data(s.model);
  const int too_few = static_cast<int>(s.candidates.size()) - 1;
  try {
    write_numeric_observation(s.model, data, s.input(s.wall, kSpan), too_few, out.rows());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "max_candidates");
    EXPECT_NE(e.problem().find("more than " + std::to_string(too_few)), std::string::npos) << e.problem();
  }
}

// The shoulder or hip the reach features measure from, found independently of the reach
// envelope: the origin of the first joint of the limb's chain past the root, after FK.
Eigen::Vector3d limb_root_by_kinematics(const BodyModel& model, const Posture& posture, Limb limb) {
  BodyData data(model);
  forward_kinematics(model, data, posture);
  for (const int joint : model.chains[operational_point(limb)]) {
    if (joint >= kRootDof) return data.placements[joint].origin;
  }
  ADD_FAILURE() << "the limb's chain has no joint past the root";
  return Eigen::Vector3d::Zero();
}

TEST(NumericObservation, ReachFeaturesPlaceEachCandidateFromTheFreeLimbsShoulderAndTheHeldHolds) {
  StartState s;
  ObservationStorage out;
  BodyData data(s.model);
  write_numeric_observation(s.model, data, s.input(s.wall, kSpan), kSlots, out.reach_rows());

  const Limb free = s.mdp.configuration().free_limb();
  const Eigen::Vector3d shoulder = limb_root_by_kinematics(s.model, s.mdp.posture(), free);
  const auto count = static_cast<int>(s.candidates.size());
  for (int slot = 0; slot < kSlots; ++slot) {
    const float* row = out.reach.data() + kReachFeatures * slot;
    if (slot >= count) {
      for (int k = 0; k < kReachFeatures; ++k) EXPECT_EQ(row[k], 0.0F) << "padding slot " << slot;
      continue;
    }
    const Eigen::Vector3d candidate = s.wall.holds[s.candidates[slot]].position;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(row[k], candidate[k] - shoulder[k], 1e-6) << "slot " << slot;
    EXPECT_NEAR(row[3], (candidate - shoulder).norm(), 1e-6);
    int column = 4;
    for (int limb = 0; limb < kLimbCount; ++limb) {
      const int hold = s.mdp.configuration().holds[limb];
      if (hold == kFree) continue;
      EXPECT_NEAR(row[column++], (candidate - s.wall.holds[hold].position).norm(), 1e-6) << "limb " << limb;
    }
  }
}

TEST(NumericObservation, MarksTheMovesThatFailedFromThisStateAndNoOther) {
  StartState s;
  ASSERT_GE(s.candidates.size(), 3U);
  ObservationStorage out;
  BodyData data(s.model);
  const std::vector<int> failed{s.candidates[2], s.candidates[0]};
  NumericObservationInput input = s.input(s.wall, kSpan);
  input.failed_holds = failed;
  write_numeric_observation(s.model, data, input, kSlots, out.reach_rows());
  for (int slot = 0; slot < kSlots; ++slot) {
    EXPECT_EQ(out.failed[slot], slot == 0 || slot == 2 ? 1.0F : 0.0F) << "slot " << slot;
  }
}

}  // namespace
}  // namespace crux
