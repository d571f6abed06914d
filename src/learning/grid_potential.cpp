#include "learning/grid_potential.hpp"

#include <algorithm>
#include <limits>

namespace crux {

GridPotential::GridPotential(const QTable& transferred) {
  transferred.for_each_row([&](StateCode s, std::span<const double> values, std::span<const std::uint32_t> visits) {
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < values.size(); ++a) {
      if (visits[a] > 0) best = std::max(best, values[a]);
    }
    if (best > -std::numeric_limits<double>::infinity()) best_[s] = best;
  });
}

double GridPotential::operator()(StateCode grid_state) const {
  const auto it = best_.find(grid_state);
  return it == best_.end() ? 0.0 : it->second;
}

}  // namespace crux
