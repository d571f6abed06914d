#pragma once
// Dyna-Q with two Q-tables learnt in parallel (paper, Algorithm 2): Q_wall on
// problem-space couples and Q_grid on agent-space couples. Real steps update both;
// the deterministic model, learnt in problem space, replays experienced pairs (50 per
// real step by default) into both: drawn uniformly (Algorithm 2), or by prioritized
// sweeping, which replays first the pairs whose Q_wall value is most out of date and
// then their predecessors, so that a change of value travels back along the paths
// that lead to it.

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <absl/container/flat_hash_map.h>

#include "learning/action_selection.hpp"
#include "learning/deterministic_model.hpp"
#include "learning/grid_potential.hpp"
#include "learning/prioritized_sweeping.hpp"
#include "learning/q_learning.hpp"
#include "learning/transfer_mode.hpp"

namespace crux {

enum class Planner { Uniform, Prioritized };
template <>
struct EnumNames<Planner> {
  static constexpr std::array<EnumName<Planner>, 2> entries{
      {{Planner::Uniform, "uniform"}, {Planner::Prioritized, "prioritized"}}};
};

struct DynaParameters {
  QLearningRates rates;
  int planning_steps = 50;  // model updates per real step
  double epsilon = 0.1;     // Algorithm 3; the paper gives no value (docs/MODEL.md, choice C19)
  Planner planner = Planner::Uniform;
  double priority_threshold = 1e-6;  // prioritized sweeping queues larger |TD errors| only
  TransferMode transfer = TransferMode::Paper;
};

// Randomness comes from named streams of `seed` (action selection's, and "planning"),
// addressed by the number of real steps learnt so far: runs with the same seed share
// their draws iteration by iteration.
class DynaQAgent {
 public:
  DynaQAgent(int wall_action_count, int grid_action_count, const DynaParameters& parameters, std::uint64_t seed);

  // Starts from a Q_grid learnt elsewhere (transfer); its visit counts say what has
  // "already been taken" in agent space. The seeded, shaping and ordered modes also keep
  // it unchanged, as the source of seeds, of the potential or of the tie order.
  void set_q_grid(QTable q_grid);

  // Remembers which actions a state offers, for the max of the updates that lead to it:
  // every candidate's wall action, and the grid actions that map back to a candidate.
  // In the seeded mode, a state seen for the first time has its Q_wall pairs seeded.
  void observe(const StateCouple& state, std::span<const ActionCandidate> candidates);

  // Algorithm 3, or the rule of the transfer mode. scores: the network mode's, one per
  // candidate (none: the mode's rule without them, which is the seeded rule).
  ActionChoice choose(const StateCouple& state, std::span<const ActionCandidate> candidates,
                      std::span<const double> scores = {});

  // Algorithm 2, lines 22-29. The next state must have been observed.
  void learn(const Experience& experience);

  // Planning updates made so far: planning_steps per real step with the uniform
  // planner, up to that with prioritized sweeping, which stops when its queue is empty.
  std::uint64_t planning_updates() const { return planning_updates_; }

  const QTable& q_wall() const { return q_wall_; }
  const QTable& q_grid() const { return q_grid_; }
  const DeterministicModel& model() const { return model_; }

  // Everything learnt and the step counters that address the random streams, for a
  // run's checkpoint: an agent that loads it continues as the saved one would have.
  void save_state(CheckpointWriter& out) const;
  void load_state(CheckpointReader& in);

 private:
  void update_both(const Experience& e);
  // The reward Q_wall learns from: e's, plus the shaping term in the shaping mode.
  double wall_reward(const Experience& e) const;
  void plan_uniformly();
  void sweep(StateCode real_state, std::size_t real_entry);
  // Queues `entry` at its Q_wall |TD error| if that passes the threshold. `exact`: the
  // pair was just updated, so its error replaces what was queued (and may drop it).
  void prioritize(std::size_t entry, bool exact);
  std::span<const ActionCode> available(const absl::flat_hash_map<StateCode, std::vector<ActionCode>>& known,
                                        StateCode state) const;

  DynaParameters settings_;
  SelectionStreams selection_streams_;
  RandomStream planning_stream_;
  std::uint64_t steps_ = 0, planning_updates_ = 0;
  QTable q_wall_, q_grid_;
  DeterministicModel model_;  // tracks predecessors for prioritized sweeping only
  PriorityQueue queue_;
  absl::flat_hash_map<StateCode, std::vector<ActionCode>> wall_actions_, grid_actions_;
  // The transferred Q_grid, unchanged: the seeds of the seeded mode, the tie order of the ordered one.
  std::optional<QTable> transferred_;
  GridPotential potential_;          // shaping mode: of the transferred Q_grid (0 without one)
  std::vector<char> grid_excluded_;  // informed mode: choose()'s per-candidate buffer
};

}  // namespace crux
