#include "ik/wall_clearance.hpp"

#include <algorithm>

#include "body/wall_penetration.hpp"

namespace crux {

double WallClearance::cost() const {
  double sum = 0.0;
  for (int r = 0; r < rows; ++r) sum += excess[r] * excess[r];
  return 0.5 * sum;
}

void wall_clearance(const BodyModel& model, const BodyData& data, WallClearance& out) {
  out.rows = 0;
  for (std::size_t v = 0; v < model.visuals.size(); ++v) {
    const BodyVisual& visual = model.visuals[v];
    if (!counts_for_the_wall(model, visual)) continue;
    const double excess = deepest_point(visual, data.placements[visual.joint]).x() - kWallSkinMargin;
    if (!(excess > 0.0)) continue;
    int row = out.rows;
    if (row == kMaxWallRows) {  // full: replace the shallowest if this one is deeper
      row = static_cast<int>(std::min_element(out.excess.begin(), out.excess.end()) - out.excess.begin());
      if (out.excess[row] >= excess) continue;
    } else {
      ++out.rows;
    }
    out.excess[row] = excess;
    deepest_x_gradient(model, data, static_cast<int>(v), out.gradient[row]);
  }
}

}  // namespace crux
