#include "configurations/filter_statistics.hpp"

namespace crux {

namespace {

using ReadingCounts = std::array<FilterCounts, kFeetAboveHandsReadings.size()>;

// Rules that do not depend on the reading, evaluated once per configuration.
bool passes_common_rules(const Wall& wall, const HoldConfiguration& c, const FilterParameters& p) {
  return (!p.reject_crossed_arms || arms_not_crossed(wall, c)) &&
         (!p.reject_crossed_legs || legs_not_crossed(wall, c)) && span_within_reach(wall, c, p.max_span_m);
}

void count(const Wall& wall, const HoldConfiguration& c, const FilterParameters& p, bool complete,
           ReadingCounts& counts) {
  const bool common = passes_common_rules(wall, c, p);
  for (std::size_t r = 0; r < kFeetAboveHandsReadings.size(); ++r) {
    FilterCounts& out = counts[r];
    (complete ? out.configurations4 : out.configurations3) += 1;
    if (common && feet_not_above_hands(wall, c, kFeetAboveHandsReadings[r])) (complete ? out.pass4 : out.pass3) += 1;
  }
}

}  // namespace

std::array<FilterCounts, kFeetAboveHandsReadings.size()> filter_statistics(const std::vector<Wall>& walls,
                                                                           const FilterParameters& parameters,
                                                                           const std::function<void(int)>& progress) {
  ReadingCounts counts{};
  int done = 0;
  for (const Wall& wall : walls) {
    const int n = wall.hold_count();
    HoldConfiguration c;
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        if (b == a) continue;
        for (int d = 0; d < n; ++d) {
          if (d == a || d == b) continue;
          // The three held limbs around each free limb: (a, b, d) in limb order.
          for (int free = 0; free < kLimbCount; ++free) {
            int slot = 0;
            const int held[3] = {a, b, d};
            for (int limb = 0; limb < kLimbCount; ++limb) c.holds[limb] = limb == free ? kFree : held[slot++];
            count(wall, c, parameters, false, counts);
          }
          for (int e = 0; e < n; ++e) {
            if (e == a || e == b || e == d) continue;
            c.holds = {a, b, d, e};
            count(wall, c, parameters, true, counts);
          }
        }
      }
    }
    if (progress) progress(++done);
  }
  return counts;
}

}  // namespace crux
