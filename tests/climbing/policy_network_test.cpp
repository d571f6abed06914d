#include "climbing/policy_network.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "body/kinematics.hpp"
#include "climbing/climbing_mdp.hpp"
#include "common/input_error.hpp"
#include "support/allocation_counter.hpp"
#include "support/climb_start.hpp"
#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

constexpr double kPolicySpan = 2.8;  // filter.max_span's default
// Input columns of the first layer: the state's 55, then the slot's 11.
constexpr int kToFinishColumn = kPolicyStateInputs - 1;
constexpr int kCandidateZColumn = kPolicyStateInputs + 2;
constexpr int kFailedColumn = kPolicyStateInputs + kPolicySlotInputs - 1;

std::string row_reading(int column, double weight) {
  std::vector<double> row(kPolicyStateInputs + kPolicySlotInputs, 0.0);
  row[column] = weight;
  return fmt::format("[{}]", fmt::join(row, ", "));
}

// Three hidden units, each reading one input: the move failed (x1), the candidate's
// height over the grasp point (x1) and the height left to the finish (x1), all over the
// span; the score is 10 h0 + h1 + 2 h2 + 0.5 with h = ReLU.
std::string small_policy(const std::string& observation = "reach", const std::string& first_row_extra = "") {
  return fmt::format(
      R"({{"format": "crux-policy", "version": 1, "observation": "{}", "max_candidates": 32, "max_span": {},
          "activation": "relu",
          "slot_layers": [{{"weight": [{}, {}, {}{}], "bias": [0, 0, 0]}},
                          {{"weight": [[10, 1, 2]], "bias": [0.5]}}],
          "value_layers": []}})",
      observation, kPolicySpan, row_reading(kFailedColumn, 1), row_reading(kCandidateZColumn, 1),
      row_reading(kToFinishColumn, 1), first_row_extra);
}

TEST(PolicyNetwork, ScoresEachCandidateAsTheLayersSayByHand) {
  const testing::ClimbStart s;
  const PolicyNetwork network = load_policy_network(testing::write_temporary("policy.json", small_policy()).string());
  ASSERT_EQ(network.slot_layers.size(), 2U);
  PolicyWorkspace workspace(s.model, network, s.wall.hold_count());
  const std::vector<int> failed{s.candidates[1]};
  std::vector<double> scores(s.candidates.size());
  score_candidates(
      s.model, network, workspace,
      {s.wall, s.mdp.configuration(), s.mdp.posture(), s.centre_of_mass, s.candidates, kPolicySpan, failed}, scores);
  const double to_finish = std::max(0.0, (s.wall.finish_height - s.centre_of_mass.z()) / kPolicySpan);
  for (std::size_t i = 0; i < s.candidates.size(); ++i) {
    const double height = (s.wall.holds[s.candidates[i]].position.z() - s.grasp.z()) / kPolicySpan;
    const double expected = 10.0 * (i == 1 ? 1.0 : 0.0) + std::max(0.0, height) + 2.0 * to_finish + 0.5;
    EXPECT_NEAR(scores[i], expected, 1e-5) << "candidate " << i << " (hold " << s.candidates[i] << ")";
  }
}

TEST(PolicyNetwork, ScoringAllocatesNothing) {
  const testing::ClimbStart s;
  const PolicyNetwork network = load_policy_network(testing::write_temporary("policy.json", small_policy()).string());
  PolicyWorkspace workspace(s.model, network, s.wall.hold_count());
  std::vector<double> scores(s.candidates.size());
  const NumericObservationInput input{s.wall,           s.mdp.configuration(), s.mdp.posture(),
                                      s.centre_of_mass, s.candidates,          kPolicySpan};
  score_candidates(s.model, network, workspace, input, scores);
  const long before = testing::allocation_count();
  score_candidates(s.model, network, workspace, input, scores);
  EXPECT_EQ(testing::allocation_count(), before);
}

// Each bad file: one InputError naming the file and saying what is wrong.
TEST(PolicyNetwork, RefusesWhatIsNotAReachPolicyNamingTheFile) {
  const std::string wrong_inputs = R"({"format": "crux-policy", "version": 1, "observation": "reach",
      "max_span": 2.8, "activation": "relu", "slot_layers": [{"weight": [[1, 2]], "bias": [0]}]})";
  const std::string two_scores = R"({"format": "crux-policy", "version": 1, "observation": "reach",
      "max_span": 2.8, "activation": "relu", "slot_layers": [{"weight": [)" +
                                 row_reading(0, 1) + ", " + row_reading(1, 1) + R"(], "bias": [0, 0]}]})";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"{not json", "not JSON"},
      {R"({"format": "something else"})", "not a policy file"},
      {small_policy("numeric"), "a policy for the \"numeric\" observation"},
      {wrong_inputs, "a layer of 2 inputs where 66 belong"},
      {two_scores, "ends in 2 outputs, not one score"},
      {testing::replaced(small_policy(), "\"bias\": [0.5]", "\"bias\": [0.5, 1]"), "has 2 values, not 1"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string path = testing::write_temporary(fmt::format("bad_{}.json", i), cases[i].first).string();
    try {
      load_policy_network(path);
      ADD_FAILURE() << "expected an InputError for case " << i;
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), path);
      EXPECT_NE(e.problem().find(cases[i].second), std::string::npos) << e.problem();
    }
  }
  const std::string missing = testing::temporary_path("missing.json").string();
  try {
    load_policy_network(missing);
    ADD_FAILURE() << "expected an InputError for a missing file";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), missing);
  }
}

}  // namespace
}  // namespace crux
