#pragma once
// The static model's effort along a climb (docs/OUTPUTS.md, "crux report"): for each
// stance of the climb, from the start, its effort on its four holds and on the three left
// when the next limb lets go, beside the limit 1 above which the stance cannot be held.

#include <string>
#include <vector>

namespace crux {

struct EffortAlongClimb {
  std::string title;
  // One per stance, the start first; +infinity where no forces balance the stance.
  std::vector<double> on_four_holds, on_three_holds;
};

// A standalone SVG document; deterministic. std::invalid_argument when the two series
// differ in length or are empty.
std::string render_effort_plot(const EffortAlongClimb& efforts);

}  // namespace crux
