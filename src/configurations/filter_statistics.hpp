#pragma once
// The share of 3- and 4-configurations that pass the geometric filter (section III-C
// reports 7.3 % and 1.4 % over 20 random walls), for every reading of "both feet above
// the hands" at once.

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "configurations/geometric_filter.hpp"

namespace crux {

struct FilterCounts {
  std::uint64_t configurations3 = 0, configurations4 = 0;  // all, over every wall
  std::uint64_t pass3 = 0, pass4 = 0;
  double share3() const { return configurations3 ? static_cast<double>(pass3) / configurations3 : 0.0; }
  double share4() const { return configurations4 ? static_cast<double>(pass4) / configurations4 : 0.0; }
};

// One entry per reading, in the order of kFeetAboveHandsReadings. A 3-configuration is
// a free limb and three distinct holds for the others; a 4-configuration four distinct
// holds. `parameters.feet_above_hands` is ignored (every reading is counted).
std::array<FilterCounts, kFeetAboveHandsReadings.size()> filter_statistics(
    const std::vector<Wall>& walls, const FilterParameters& parameters,
    const std::function<void(int walls_done)>& progress = {});

}  // namespace crux
