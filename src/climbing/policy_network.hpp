#pragma once
// A climbing policy learnt across many walls (examples/python/policy_baseline.py,
// docs/BASELINES.md), read from its plain-weights JSON file and evaluated with Eigen: a
// score for each candidate of a climbing state, from crux.gym's reach observation. The
// network transfer mode (learning/transfer_mode.hpp) orders exploration by these scores.
// The network (immutable, shared) is apart from its workspace (one per thread).

#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "body/body_data.hpp"
#include "climbing/numeric_observation.hpp"

namespace crux {

// What the network reads: the state's 55 numbers (the free limb 4, the held holds 12, the
// root 3, the joint angles 32, the centre of mass 3, the height to the finish 1) and each
// slot's 11 (the candidate 3, its reach features 7, whether its move failed 1), lengths
// divided by the span the policy was trained with.
inline constexpr int kPolicyStateInputs = 4 + 3 * kLimbCount + kConfigurationDof + 3 + 1;
inline constexpr int kPolicySlotInputs = 3 + kReachFeatures + 1;

struct PolicyLayer {
  Eigen::MatrixXf weight;  // outputs x inputs
  Eigen::VectorXf bias;
};

struct PolicyNetwork {
  std::string source;     // the file it was read from, for messages
  double max_span_m = 0;  // filter.max_span in training: the observation's bounds and scale
  // ReLU between layers; the first reads [state, slot], the last gives one score.
  std::vector<PolicyLayer> slot_layers;
};

// InputError naming the file when it cannot be read, is not JSON, is not a policy file,
// is a policy for another observation form or format version, or its layers do not chain
// from kPolicyStateInputs + kPolicySlotInputs inputs to one score.
PolicyNetwork load_policy_network(const std::string& path);

// Buffers sized once for a wall of at most max_candidates candidates a state.
struct PolicyWorkspace {
  PolicyWorkspace(const BodyModel& model, const PolicyNetwork& network, int max_candidates);
  int max_candidates;
  BodyData body;
  std::vector<float> free_limb, held, candidates, mask, posture, centre_of_mass, to_finish, reach, failed;
  Eigen::VectorXf state, first_from_state;
  Eigen::MatrixXf slots, hidden, next;  // one column per candidate
};

// The network's score of each candidate of `state`, in the order of state.candidate_holds
// (each is scored alone: any order). The observation is the one the network was trained
// on only when state.max_span_m is network.max_span_m (experiments/run_inputs checks it).
void score_candidates(const BodyModel& model, const PolicyNetwork& network, PolicyWorkspace& workspace,
                      const NumericObservationInput& state, std::span<double> scores);

}  // namespace crux
