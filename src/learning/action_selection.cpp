#include "learning/action_selection.hpp"

#include <stdexcept>

namespace crux {

namespace {

// Tie-break draws of the two tables are told apart by the low bit of the draw number.
constexpr std::uint64_t kWallTable = 0, kGridTable = 1;

// Index of a best candidate by `value` among those `eligible`, ties going to the best
// random priority of their `code`; -1 if none is eligible.
template <typename Value, typename Code, typename Eligible>
long best_candidate(std::span<const ActionCandidate> candidates, Value value, Code code, Eligible eligible,
                    const RandomStream& tie_break, std::uint64_t iteration, std::uint64_t table) {
  long best = -1;
  double best_value = 0.0;
  std::uint64_t best_priority = 0;
  bool tied = false;  // best_priority is drawn only once a tie appears
  const auto priority = [&](std::size_t i) {
    return tie_break.bits(iteration, 2 * static_cast<std::uint64_t>(code(candidates[i])) + table);
  };
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!eligible(candidates[i])) continue;
    const double v = value(candidates[i]);
    if (best < 0 || v > best_value) {
      best = static_cast<long>(i);
      best_value = v;
      tied = false;
    } else if (v == best_value) {
      if (!tied) best_priority = priority(static_cast<std::size_t>(best)), tied = true;
      if (const std::uint64_t p = priority(i); p < best_priority) best = static_cast<long>(i), best_priority = p;
    }
  }
  return best;
}

}  // namespace

ActionChoice select_action(const QTable& q_wall, const QTable& q_grid, const StateCouple& state,
                           std::span<const ActionCandidate> candidates, double epsilon, const SelectionStreams& streams,
                           std::uint64_t iteration, const SelectionRule& rule) {
  if (candidates.empty()) throw std::invalid_argument("select_action: a state without possible actions");
  long w = best_candidate(
      candidates, [&](const ActionCandidate& c) { return q_wall.value(state.wall, c.wall); },
      [](const ActionCandidate& c) { return c.wall; }, [](const ActionCandidate&) { return true; }, streams.tie_break,
      iteration, kWallTable);
  if (!rule.wall_tie_scores.empty()) {
    if (rule.wall_tie_scores.size() != candidates.size()) {
      throw std::invalid_argument("select_action: wall_tie_scores needs one score per candidate");
    }
    const double best_wall_value = q_wall.value(state.wall, candidates[w].wall);
    w = best_candidate(
        candidates, [&](const ActionCandidate& c) { return rule.wall_tie_scores[&c - candidates.data()]; },
        [](const ActionCandidate& c) { return c.wall; },
        [&](const ActionCandidate& c) { return q_wall.value(state.wall, c.wall) == best_wall_value; },
        streams.tie_break, iteration, kWallTable);
  } else if (rule.wall_tie_order != nullptr) {
    const QTable& order = *rule.wall_tie_order;
    const double best_wall_value = q_wall.value(state.wall, candidates[w].wall);
    const long ordered = best_candidate(
        candidates, [&](const ActionCandidate& c) { return order.value(state.grid, c.grid); },
        [](const ActionCandidate& c) { return c.wall; },
        [&](const ActionCandidate& c) {
          return q_wall.value(state.wall, c.wall) == best_wall_value && c.represents_grid_action &&
                 order.taken(state.grid, c.grid);
        },
        streams.tie_break, iteration, kWallTable);
    if (ordered >= 0) w = ordered;
  }
  if (streams.epsilon.uniform(iteration, 0) > epsilon &&
      (!rule.wall_requires_taken || q_wall.taken(state.wall, candidates[w].wall))) {
    return {static_cast<std::size_t>(w), Regime::WGreedy};
  }
  if (rule.grid_greedy) {
    const auto eligible = [&](const ActionCandidate& c) {
      return c.represents_grid_action &&
             (rule.grid_excluded.empty() || rule.grid_excluded[&c - candidates.data()] == 0) &&
             (!rule.grid_taken_only || q_grid.taken(state.grid, c.grid));
    };
    const long g = best_candidate(
        candidates, [&](const ActionCandidate& c) { return q_grid.value(state.grid, c.grid); },
        [](const ActionCandidate& c) { return c.grid; }, eligible, streams.tie_break, iteration, kGridTable);
    if (g >= 0 && streams.epsilon.uniform(iteration, 1) > epsilon && q_grid.taken(state.grid, candidates[g].grid)) {
      return {static_cast<std::size_t>(g), Regime::GGreedy};
    }
  }
  std::size_t chosen = 0;
  std::uint64_t chosen_priority = UINT64_MAX;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (const std::uint64_t p = streams.random_action.bits(iteration, static_cast<std::uint64_t>(candidates[i].wall));
        p < chosen_priority) {
      chosen = i, chosen_priority = p;
    }
  }
  return {chosen, Regime::Random};
}

}  // namespace crux
