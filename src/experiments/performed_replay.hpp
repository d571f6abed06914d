#pragma once
// The movement of a climb performed in MuJoCo, for the report's 3D replay (docs/OUTPUTS.md,
// "The replay data"): its frames are the simulation's recorded samples (trajectory.csv),
// with the root's rotation and each limb's force from its hold, not the IK's drawing; each
// move attempted keeps its outcome, so that a failed move is shown with its cause.

#include <array>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "configurations/hold_configuration.hpp"
#include "configurations/reachability.hpp"
#include "simulation/climb_trajectory.hpp"
#include "simulation/performed_move.hpp"
#include "wall/wall.hpp"

namespace crux {

// A move of a performed climb as its folder records it (perform.json's moves).
struct AttemptedMove {
  Limb limb = Limb::RightHand;
  int hold = 0;  // its index in the wall
  bool performed = false;
  MoveFailure cause = MoveFailure::None;
  double max_torque_ratio = 0.0;
};

struct PerformedReplayMove {
  AttemptedMove move;
  HoldConfiguration configuration;  // after a performed move, else the one the body stays on
  int first_frame = 0, last_frame = 0;
};

struct PerformedReplay {
  int frame_count = 0;
  // Per frame: kConfigurationDof posture values, the root's rotation from its orientation on
  // the wall (x, y, z, w), each limb's force from its hold (N, wall coordinates, 3 per limb)
  // and the simulated time (s); rounded to 1e-5 to keep the page small.
  std::vector<double> postures, root_rotations, hold_forces, times;
  std::vector<PerformedReplayMove> moves;
  // A frame (-1: none) and its grasp points by crux's forward kinematics turned by the
  // root's rotation, which the page must reproduce from the rounded values it reads.
  int check_frame = -1;
  std::array<Eigen::Vector3d, kLimbCount> check_grasp_points{};
};

// `moves` are the climb's attempted moves from its start on `wall` (performed but perhaps
// the last), `trajectory` its samples, whose move indices (-1 while the start settles)
// must not decrease and must name an attempted move. InputError naming `source` otherwise.
PerformedReplay replay_performed_climb(const BodyModel& model, const Wall& wall, std::span<const AttemptedMove> moves,
                                       std::span<const TrajectorySample> trajectory, const std::string& source);

}  // namespace crux
