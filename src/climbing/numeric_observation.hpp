#pragma once
// What a function approximator sees of a climbing state: crux.gym's "numeric"
// observation (docs/PYTHON.md). Every position is taken relative to the free limb's
// grasp point, so that one network acts on any wall; the candidate holds fill a fixed
// number of slots, padded and masked. Written as float32 into the caller's storage (one
// environment's rows of the batched arrays), computed once here for the single and the
// vector environment alike.

#include <span>

#include "body/body_data.hpp"
#include "configurations/hold_configuration.hpp"
#include "wall/wall.hpp"

namespace crux {

// The reach form's features of one candidate slot (docs/BASELINES.md, "What the observation
// tells of reachability"): the candidate relative to the free limb's shoulder or hip (3),
// that distance (1), and its distance to each held hold in limb order (3).
inline constexpr int kReachFeatures = 7;

// Where one observation goes; sizes in floats.
struct NumericObservationRows {
  float* free_limb;       // 4: one-hot
  float* held;            // 4 x 3: each limb's hold, 0 for the free limb
  float* candidates;      // max_candidates x 3: the candidate holds, 0 past them
  float* candidate_mask;  // max_candidates: 1 for a candidate, 0 for padding
  float* posture;         // kConfigurationDof: the root relative to the grasp point, then the joint angles
  float* centre_of_mass;  // 3
  float* to_finish;       // 1: the finishing height less the centre of mass's, clipped to +-2 max_span
  // The reach form only (null for the numeric form):
  float* candidate_reach = nullptr;   // max_candidates x kReachFeatures, 0 past the candidates
  float* candidate_failed = nullptr;  // max_candidates: 1 for a move that failed from this state
};

struct NumericObservationInput {
  const Wall& wall;
  const HoldConfiguration& configuration;  // a 3-configuration: its free limb's grasp point is the origin
  const Posture& posture;
  const Eigen::Vector3d& centre_of_mass;
  std::span<const int> candidate_holds;  // in the order of the slots
  double max_span_m;                     // filter.max_span, the bound of to_finish
  // The holds whose move failed since the climber entered this state, in any order: a
  // failed move leaves the state as it was, and this is what tells a greedy policy not to
  // try it again.
  std::span<const int> failed_holds = {};
};

// InputError naming max_candidates when the state offers more candidates than slots.
// `data` is the caller's workspace (forward kinematics of the posture).
void write_numeric_observation(const BodyModel& model, BodyData& data, const NumericObservationInput& state,
                               int max_candidates, const NumericObservationRows& out);

}  // namespace crux
