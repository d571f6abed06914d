#pragma once
// Climbing-like IK queries, for comparing solvers (crux ik-compare), benchmarks and
// tests: from a posture that grasps four holds, one limb moves to a new hold up to
// about 1 m away, keeping the layout natural (limbs uncrossed, feet below hands); a
// share of queries are clearly unreachable (the hold is moved 2.5 to 3.5 m away, so
// two holds are about 3 m apart).

#include <cstdint>
#include <vector>

#include "ik/ik_solver.hpp"
#include "ik/root_target.hpp"

namespace crux {

struct ReachQuery {
  Posture start;
  ReachTarget target;
  Limb moved_limb = Limb::RightHand;
  bool far_move = false;  // generated as a clearly unreachable query
};

struct ReachQueryParameters {
  double max_move_m = 1.0;
  double far_share = 0.15;
  double far_move_min_m = 2.5;
  double far_move_max_m = 3.5;
  int restart_every = 25;  // the walk returns to the start posture this often
  RootTargetParameters root;
};

// Four holds in the start layout (docs/MODEL.md, choice C5) on a regular 0.3 m x 0.5 m grid (feet on row 0,
// hands on row 3, columns 1 and 3 counted from the climber's right).
std::array<Eigen::Vector3d, kLimbCount> start_layout_holds();

// Solves the start layout from the standing posture placed at H(C4); throws
// InputError("ik", ...) if the solver, with those parameters, cannot reach it.
Posture start_layout_posture(const BodyModel& model, const IkParameters& parameters,
                             const RootTargetParameters& root = {});

// `count` queries of a random climbing walk driven by `walk_settings` (its successful
// moves become the next start postures). Deterministic in `seed`.
std::vector<ReachQuery> climbing_reach_queries(const BodyModel& model, const IkParameters& walk_settings, int count,
                                               std::uint64_t seed, const ReachQueryParameters& parameters = {});

}  // namespace crux
