#pragma once
// Dyna's learnt model (Algorithm 2, line 24): the last (s', r) seen for each
// problem-space pair (s, a), with the agent-space descriptors of s, a and s' so that
// planning can update both tables. Pairs are kept in first-seen order so that a uniform
// draw over them is reproducible; each state knows the pairs that lead to it, for
// prioritized sweeping.

#include <span>
#include <vector>

#include <absl/container/flat_hash_map.h>

#include "learning/q_table.hpp"

namespace crux {

class CheckpointWriter;
class CheckpointReader;

// A transition in both representations; grid_action is kNoAction when the action's
// hold lies outside the grid.
struct Experience {
  StateCode wall_state = 0, grid_state = 0;
  ActionCode wall_action = kNoAction, grid_action = kNoAction;
  double reward = 0.0;
  StateCode next_wall_state = 0, next_grid_state = 0;
};

class DeterministicModel {
 public:
  explicit DeterministicModel(bool track_predecessors = false) : track_predecessors_(track_predecessors) {}

  // Returns the pair's index (its rank in first-seen order).
  std::size_t record(const Experience& experience);
  std::size_t size() const { return entries_.size(); }
  const Experience& at(std::size_t index) const { return entries_[index]; }
  // The last recorded experience of (wall_state, wall_action), or nullptr.
  const Experience* find(StateCode wall_state, ActionCode wall_action) const;
  // Indices of the pairs whose last recorded next state is `wall_state` (empty unless
  // predecessors are tracked).
  std::span<const std::size_t> predecessors(StateCode wall_state) const;

  // Every pair and predecessor list, for a run's checkpoint (load_state replaces them).
  void save_state(CheckpointWriter& out) const;
  // Actions outside [0, wall_actions) or [kNoAction, grid_actions) fail the reader.
  void load_state(CheckpointReader& in, int wall_actions, int grid_actions);

 private:
  struct PairKey {
    StateCode state;
    ActionCode action;
    bool operator==(const PairKey&) const = default;
  };
  struct PairHash {
    std::size_t operator()(const PairKey& k) const noexcept {
      return std::hash<StateCode>()(k.state * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(k.action));
    }
  };
  absl::flat_hash_map<PairKey, std::size_t, PairHash> index_;
  std::vector<Experience> entries_;
  bool track_predecessors_;
  absl::flat_hash_map<StateCode, std::vector<std::size_t>> predecessors_;
};

}  // namespace crux
