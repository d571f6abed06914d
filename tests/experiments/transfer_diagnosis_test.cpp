#include "experiments/transfer_diagnosis.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

IterationRecord record(Regime regime, int hold, bool success, std::uint32_t grid_state, ActionCode tile, float dy,
                       float dz, bool back = false) {
  IterationRecord r{0, regime, hold, success, success ? 0.02 : 0.0, success ? -1.0 : -1000.0};
  r.grid_state = grid_state;
  r.tile = tile;
  r.tile_offset_y = dy;
  r.tile_offset_z = dz;
  r.back_to_left_hold = back;
  return r;
}

TEST(TransferDiagnosis, ProfilesTransfersChoicesAgainstTheEvidenceByHand) {
  ExperimentResult result;
  for (ConditionResult& c : result.conditions) c.runs.resize(1);
  // Training tried pair (state 7, tile 3) twice, at offsets (0, 0) and (0.1, 0), once
  // successfully: mean offset (0.05, 0).
  result.conditions[static_cast<int>(Condition::Training)].runs[0].iterations = {
      record(Regime::Random, 1, true, 7, 3, 0.0f, 0.0f), record(Regime::Random, 2, false, 7, 3, 0.1f, 0.0f)};
  // Transfer: g-greedy tries the pair with a hold at (0.05, 0.12): 12 cm from the mean,
  // far, and fails; g-greedy tries the same hold again (a repeat of a failure, left out
  // of the evidence measures); a random
  // action goes back to the hold just left, outside the grid; the fourth lies beyond
  // the window.
  result.conditions[static_cast<int>(Condition::Transfer)].runs[0].iterations = {
      record(Regime::GGreedy, 5, false, 7, 3, 0.05f, 0.12f), record(Regime::GGreedy, 5, false, 7, 3, 0.05f, 0.12f),
      record(Regime::Random, 9, true, 8, kNoAction, 0.0f, 0.0f, true), record(Regime::GGreedy, 6, true, 7, 3, 0, 0)};
  const auto profiles = diagnose_transfer(result, 3);
  const ChoiceProfile& g = profiles[static_cast<int>(Regime::GGreedy)];
  EXPECT_EQ(g.actions, 2);
  EXPECT_EQ(g.successes, 0);
  EXPECT_EQ(g.repeats_of_failure, 1);
  EXPECT_EQ(g.with_evidence, 1) << "the repeat is left out of the evidence";
  EXPECT_NEAR(g.evidence_success_rate, 0.5, 1e-12) << "training's two tries, one successful";
  EXPECT_EQ(g.far, 1) << "12 cm from the training mean";
  EXPECT_EQ(g.near, 0);
  EXPECT_NEAR(g.median_distance_cm, 12.0, 1e-4);
  const ChoiceProfile& r = profiles[static_cast<int>(Regime::Random)];
  EXPECT_EQ(r.actions, 1);
  EXPECT_EQ(r.back_to_left_hold, 1);
  EXPECT_EQ(r.back_to_left_hold_successes, 1);
  EXPECT_EQ(r.with_evidence, 0) << "outside the grid there is no agent-space pair";
  EXPECT_DOUBLE_EQ(r.mean_root_rise_cm, 2.0);
  EXPECT_EQ(profiles[static_cast<int>(Regime::WGreedy)].actions, 0);
}

}  // namespace
}  // namespace crux
