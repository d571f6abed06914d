#pragma once
// Table I of the paper: per action-selection regime, the number of actions, the
// success rate (share of its actions that reached a C-reachable 4-configuration) and
// the mean vertical displacement of e0 over its successful actions, in cm (docs/MODEL.md,
// choice C21), over the first iterations of a run ("beginning") and over the whole run.

#include <array>
#include <span>
#include <vector>

#include "common/enum_names.hpp"
#include "experiments/learning_run.hpp"

namespace crux {

enum class Window { Beginning = 0, Overall = 1 };
template <>
struct EnumNames<Window> {
  static constexpr std::array<EnumName<Window>, 2> entries{
      {{Window::Beginning, "beginning"}, {Window::Overall, "overall"}}};
};

struct RegimeStats {
  double actions_per_run = 0.0;  // mean over runs
  double success_rate = 0.0;     // pooled over runs: successes / actions
  double vertical_cm = 0.0;      // pooled over runs: mean e0 rise of successful actions
  std::uint64_t actions = 0, successes = 0;
};

// Statistics of one regime over the first `iterations` of each run (all of them if
// iterations < 0).
RegimeStats regime_stats(std::span<const RunResult> runs, Regime regime, int iterations);

// [window][regime] for one condition; `beginning` is the number of iterations of the
// beginning window (2000 in the paper).
std::array<std::array<RegimeStats, kRegimeCount>, 2> table_one(std::span<const RunResult> runs, int beginning);

}  // namespace crux
