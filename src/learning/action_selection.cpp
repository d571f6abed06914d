#include "learning/action_selection.hpp"

#include <stdexcept>

namespace crux {

const char* regime_name(Regime regime) {
  switch (regime) {
    case Regime::WGreedy: return "w_greedy";
    case Regime::GGreedy: return "g_greedy";
    case Regime::Random: return "random";
  }
  return "?";
}

namespace {

// Index of a best candidate by `value`, among those `eligible`, ties broken uniformly
// (reservoir sampling over the tied ones); -1 if none is eligible.
template <typename Value, typename Eligible>
long best_candidate(std::span<const ActionCandidate> candidates, Value value, Eligible eligible, Random& random) {
  long best = -1;
  double best_value = 0.0;
  int ties = 0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!eligible(candidates[i])) continue;
    const double v = value(candidates[i]);
    if (best < 0 || v > best_value) {
      best = static_cast<long>(i);
      best_value = v;
      ties = 1;
    } else if (v == best_value && random.below(++ties) == 0) {
      best = static_cast<long>(i);
    }
  }
  return best;
}

}  // namespace

ActionChoice select_action(const QTable& q_wall, const QTable& q_grid, const StateCouple& state,
                           std::span<const ActionCandidate> candidates, double epsilon, Random& random) {
  if (candidates.empty()) throw std::invalid_argument("select_action: a state without possible actions");
  const long w = best_candidate(
      candidates, [&](const ActionCandidate& c) { return q_wall.value(state.wall, c.wall); },
      [](const ActionCandidate&) { return true; }, random);
  if (random.uniform() > epsilon && q_wall.taken(state.wall, candidates[w].wall)) {
    return {static_cast<std::size_t>(w), Regime::WGreedy};
  }
  const long g = best_candidate(
      candidates, [&](const ActionCandidate& c) { return q_grid.value(state.grid, c.grid); },
      [](const ActionCandidate& c) { return c.represents_grid_action; }, random);
  if (g >= 0 && random.uniform() > epsilon && q_grid.taken(state.grid, candidates[g].grid)) {
    return {static_cast<std::size_t>(g), Regime::GGreedy};
  }
  return {static_cast<std::size_t>(random.below(candidates.size())), Regime::Random};
}

}  // namespace crux
