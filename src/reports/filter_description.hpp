#pragma once
// crux filter-stats' output: the share of 3- and 4-configurations that pass the
// geometric filter under each reading of its feet-above-hands rule, beside the paper's.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "configurations/filter_statistics.hpp"

namespace crux {

struct FilterReport {
  int wall_count = 0;
  std::uint64_t wall_seed = 0;
  FilterParameters parameters;                                      // its reading is the selected one
  std::array<FilterCounts, kFeetAboveHandsReadings.size()> counts;  // per reading, in that order
};

nlohmann::ordered_json filter_json(const FilterReport& report);
std::string filter_text(const FilterReport& report);

}  // namespace crux
