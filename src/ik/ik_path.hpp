#pragma once
// The movement between two postures as the report's replay draws it (docs/OUTPUTS.md,
// "The replay data"): the path of the paper's gradient-descent IK (Algorithm 1) from the
// first posture towards the move's target, at equal joint-space distances, blended into
// the second posture so that the last sample is exactly it. The static model's survey
// checks these samples on the holds kept during the move (docs/PHYSICS.md).

#include <vector>

#include "body/body_data.hpp"
#include "ik/ik_solver.hpp"

namespace crux {

// `count` samples (the last is `to`) into `samples`, which keeps its capacity. `ik`'s
// solver is replaced by the paper's, whose small steps make a continuous movement. A move
// that `from` already grasps (back to the hold just left, say) needs no path: its samples
// go straight from `from` to `to`. `path` is a workspace for the solver's iterates.
void ik_path_samples(const BodyModel& model, BodyData& data, const Posture& from, const Posture& to,
                     const ReachTarget& target, const IkParameters& ik, int count, std::vector<Posture>& path,
                     std::vector<Posture>& samples);

}  // namespace crux
