#include "configurations/possible_actions.hpp"

#include <cassert>

namespace crux {

int possible_actions(const Wall& wall, const HoldConfiguration& state, const FilterParameters& parameters,
                     std::span<int> out) {
  assert(static_cast<int>(out.size()) >= wall.hold_count());
  const Limb free = state.free_limb();
  int count = 0;
  for (int hold = 0; hold < wall.hold_count(); ++hold) {
    if (hold == state.holds[0] || hold == state.holds[1] || hold == state.holds[2] || hold == state.holds[3]) continue;
    if (passes_filter(wall, state.with(free, hold), parameters)) out[count++] = hold;
  }
  return count;
}

}  // namespace crux
