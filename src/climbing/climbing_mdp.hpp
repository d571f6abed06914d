#pragma once
// The climbing MDP (paper, sections III-C and III-D, Algorithm 2): a state is a
// 3-configuration with its agent-space descriptor, an action a hold with its tile.
// A step runs IK from the current posture to the new 4-configuration with the root
// target H(C4); only this class touches the kinematics, the learner sees codes.

#include <map>
#include <memory>
#include <span>
#include <vector>

#include "agent_space/agent_descriptor.hpp"
#include "climbing/configuration_reacher.hpp"
#include "configurations/possible_actions.hpp"
#include "configurations/reachability.hpp"
#include "learning/action_selection.hpp"
#include "learning/q_learning.hpp"
#include "simulation/move_trial.hpp"

namespace crux {

struct Rewards {
  double unreachable = -1000.0;  // stay in place
  double step = -1.0;            // a reachable 4-configuration
  double finish = 200000.0;      // the centre of mass passed the finishing height
  // Subtracted per unit of a reached stance's effort (the static model's; docs/MODEL.md,
  // choice C28): 0, the paper's rewards, by default.
  double effort = 0.0;
  // Potential-based height shaping (Ng, Harada and Russell 1999; docs/MODEL.md, choice
  // C29): every step's reward gains gamma * phi(s') - phi(s), where phi(s) is `height`
  // times the mean height, along the wall, of the holds held in the 3-configuration s, and
  // phi = 0 once the climb is finished. 0 by default: the paper's rewards.
  double height = 0.0;
};

struct ClimbingParameters {
  FilterParameters filter;
  GridParameters grid;
  ReachabilityParameters reachability;
  PhysicsParameters physics;  // the kinematic model (the paper's) or the static one
  Rewards rewards;
  // A failed move also falls when the climber is stuck in its stance: in its last
  // 4-configuration no limb can move to any other hold, every such move known
  // unreachable (docs/MODEL.md, choice C31). Off by default: only C27's dead ends fall.
  bool fall_when_stuck = false;
  // physics.model = dynamic: a move the static model reaches is reached only when MuJoCo
  // performs it, alone from its planned stance (simulation/move_trial), with these settings.
  PerformParameters perform;
};

struct StepOutcome {
  bool reached = false;   // the 4-configuration was C-reachable
  bool finished = false;  // ... and the centre of mass passed the finishing height
  // Not reached, and now every candidate of the state is known unreachable: the climber
  // cannot go on and falls; the MDP is back at the start. Only the static model has such
  // dead ends (docs/MODEL.md, choice C27): under the kinematic one the hold just left is
  // always reachable again.
  bool fell = false;
  double reward = 0.0;
  double root_rise_m = 0.0;  // change of e0's height (0 when not reached)
  double effort = 0.0;       // the reached stance's under the static model (0 otherwise, and when not reached)
  Eigen::Vector3d centre_of_mass = Eigen::Vector3d::Zero();  // at the new posture (zero when not reached)
  // The posture that grasps the new 4-configuration, also on the finishing move (after
  // which the MDP is back at the start); null when not reached. Owned by the MDP's cache.
  const Posture* posture = nullptr;
};

class ClimbingMdp {
 public:
  // Solves the start configuration from standing; throws InputError naming the wall if
  // it is not reachable (such a wall is reported, never silently used).
  // `discount` is the learner's gamma, which the height shaping (Rewards::height) must use to
  // keep the optimal policy: the learning run passes its learning.gamma; by default the
  // paper's 0.9 (the Python environments, which take no learning keys).
  ClimbingMdp(const BodyModel& model, const Wall& wall, const ClimbingParameters& parameters,
              double discount = QLearningRates{}.gamma);

  // Back to the start configuration with the right hand free (Algorithm 2, lines 1-3).
  void reset();

  const StateCouple& state() const { return state_; }
  std::span<const ActionCandidate> candidates() const { return {candidates_.data(), candidate_count_}; }
  // Whether `hold` is one of the state's candidates (the geometric filter's possible
  // actions): what step requires, and what callers with their own action (Python, an
  // episode replayed from a file) check first to name it in their error.
  bool offers(ActionCode hold) const;
  // std::invalid_argument when the state does not offer `hold`.
  StepOutcome step(ActionCode hold);

  const HoldConfiguration& configuration() const { return configuration_; }
  // The moving grid of the current state, and the hold its free limb held in the last
  // 4-configuration (taking it again is a move that goes nowhere).
  const GridPlacement& placement() const { return placement_; }
  int left_hold() const { return left_hold_; }
  const Posture& posture() const { return posture_; }
  const Posture& start_posture() const { return start_posture_; }
  const ConfigurationReacher& reacher() const { return reacher_; }
  // Under physics.model = dynamic, each move the static model reaches is performed in
  // MuJoCo once (its verdict cached as the reacher's are).
  bool simulates() const { return trials_ != nullptr; }
  // The distinct moves performed in MuJoCo (each once), and how many of them were performed.
  std::size_t moves_simulated() const { return performed_.size(); }
  std::size_t moves_performed() const;
  const Wall& wall() const { return wall_; }
  int wall_action_count() const { return wall_.hold_count(); }
  int grid_action_count() const { return parameters_.grid.tile_count(); }

  // Where the climber is (configuration, posture, the hold just left) and the reacher's
  // cache, for a run's checkpoint; load_state describes the state again from them.
  void save_state(CheckpointWriter& out) const;
  void load_state(CheckpointReader& in);

 private:
  // The state couple and candidates of configuration_, with `body` placed at posture_.
  void describe(const BodyData& body);
  // Whether every candidate of the state is known unreachable.
  bool at_dead_end() const;
  // The reacher's verdict, or a move that failed in MuJoCo (physics.model = dynamic).
  bool known_unreachable(const HoldConfiguration& complete, Limb next_to_move) const;
  // Under physics.model = dynamic, whether MuJoCo performs the move to `hold` from the
  // present stance, arriving at `reached` (the reacher's posture), performed once per
  // verdict key.
  bool performed(const HoldConfiguration& complete, int hold, const Posture& reached);
  // Whether, in the last 4-configuration, every move of every limb to another hold than
  // its own is known unreachable: only letting go and grasping the same hold again is left.
  bool stuck_in_stance();
  // The paper's step, without the height shaping that step() adds.
  StepOutcome unshaped_step(ActionCode hold);
  // phi of the height shaping (Rewards::height) at the current 3-configuration.
  double height_potential() const;

  const Wall& wall_;
  ClimbingParameters parameters_;
  double discount_;
  ConfigurationReacher reacher_;
  std::unique_ptr<MoveTrials> trials_;
  std::map<std::uint64_t, bool> performed_;  // by the reacher's verdict key: ordered, for checkpoints
  Posture start_posture_, posture_;
  HoldConfiguration configuration_;  // a 3-configuration
  GridPlacement placement_;
  std::array<Eigen::Vector3d, kLimbCount> limb_bases_;  // shoulders and hips, relative to e0
  int left_hold_ = kFree;
  StateCouple state_;
  std::vector<int> possible_;
  std::vector<ActionCandidate> candidates_;
  std::size_t candidate_count_ = 0;
  std::vector<int> tile_representative_;  // per tile: candidate index nearest its centre
  std::vector<double> tile_best_distance_;
  std::vector<int> stuck_possible_;  // stuck_in_stance's buffer of possible actions
};

}  // namespace crux
