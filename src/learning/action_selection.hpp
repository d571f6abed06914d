#pragma once
// Action selection, Algorithm 3: w-greedy (the best action for Q_wall, if it has
// already been taken in this state), else g-greedy (the best action for Q_grid, if
// already taken in this agent-space state), else a random possible action; each of the
// first two also gives way to exploration with probability epsilon. A SelectionRule
// varies it for the transfer modes (learning/transfer_mode.hpp).

#include <cstdint>
#include <span>

#include "common/enum_names.hpp"
#include "common/random_stream.hpp"
#include "learning/q_table.hpp"

namespace crux {

enum class Regime : std::uint8_t { WGreedy = 0, GGreedy = 1, Random = 2 };
inline constexpr int kRegimeCount = 3;
template <>
struct EnumNames<Regime> {
  static constexpr std::array<EnumName<Regime>, kRegimeCount> entries{
      {{Regime::WGreedy, "w_greedy"}, {Regime::GGreedy, "g_greedy"}, {Regime::Random, "random"}}};
};

// A possible action in both representations. `represents_grid_action` marks, for each
// grid action, the one candidate that the grid action maps back to (the hold nearest
// its tile's centre): g-greedy may only return such a candidate.
struct ActionCandidate {
  ActionCode wall = kNoAction;
  ActionCode grid = kNoAction;
  bool represents_grid_action = false;
  // It puts the free limb back on the hold it has just left: always reachable, and it
  // returns the 4-configuration of the step before (the informed and prior modes skip it).
  bool returns_to_left_hold = false;
};

struct StateCouple {
  StateCode wall = 0;
  StateCode grid = 0;
};

struct ActionChoice {
  std::size_t candidate = 0;  // index into the candidates
  Regime regime = Regime::Random;
};

// The draws of Algorithm 3, each from its own named stream, addressed by iteration:
//   epsilon:       the two exploration tests (lines 3 and 8);
//   tie_break:     a random priority per action, the best priority winning among
//                  equally valued best actions;
//   random_action: a random priority per hold, the best priority being the random
//                  action (line 12).
// Priorities keyed by action rather than by position in the candidate list keep two
// runs coupled: if they offer overlapping actions at the same iteration, they most
// often pick the same one, while each pick stays uniform over what is offered.
struct SelectionStreams {
  explicit SelectionStreams(std::uint64_t seed)
      : epsilon(seed, "epsilon"), tie_break(seed, "tie_break"), random_action(seed, "random_action") {}
  RandomStream epsilon, tie_break, random_action;
};

// Algorithm 3 by default.
struct SelectionRule {
  bool wall_requires_taken = true;      // w-greedy only when its best action was taken before
  bool grid_greedy = true;              // the g-greedy regime; without it, w-greedy's refusal is random
  std::span<const char> grid_excluded;  // per candidate, non-zero: g-greedy may not choose it
  // g-greedy's best among the agent-space actions already taken, instead of its best
  // action being required to have been taken.
  bool grid_taken_only = false;
  // When set, w-greedy's ties (typically a state's untried actions, all at 0) go first to
  // the representatives of the agent-space actions taken in this table, the largest value
  // first; the rest of the ties, or all of them if none is taken, to the random tie-break.
  const QTable* wall_tie_order = nullptr;
  // When not empty, one score per candidate: w-greedy's ties go to the highest score,
  // equal scores to the random tie-break (wall_tie_order is then not used).
  std::span<const double> wall_tie_scores;
};

// Throws std::invalid_argument when there is no candidate.
ActionChoice select_action(const QTable& q_wall, const QTable& q_grid, const StateCouple& state,
                           std::span<const ActionCandidate> candidates, double epsilon, const SelectionStreams& streams,
                           std::uint64_t iteration, const SelectionRule& rule = {});

}  // namespace crux
