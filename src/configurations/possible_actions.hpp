#pragma once
// The possible actions of a 3-configuration (docs/MODEL.md, choice C14): the holds its free limb may
// take such that the resulting 4-configuration passes the geometric filter. Called at
// every learning step, so it writes into a caller-owned buffer and never allocates.

#include <span>

#include "configurations/geometric_filter.hpp"

namespace crux {

// Writes the possible holds (indices, ascending) into `out`, which must have room for
// wall.hold_count() entries, and returns how many there are.
int possible_actions(const Wall& wall, const HoldConfiguration& state, const FilterParameters& parameters,
                     std::span<int> out);

}  // namespace crux
