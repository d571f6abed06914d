#pragma once
// The shaping potential of the `shaping` transfer mode: phi(s) = the best value, over the
// actions already taken there, of a transferred Q_grid in s's agent-space state (0 for an
// agent-space state it never saw). The table is fixed when the potential is built, so
// phi is a function of the state alone, as potential-based shaping requires (Ng, Harada
// and Russell 1999): the shaped rewards leave the optimal policy unchanged.

#include <unordered_map>

#include "learning/q_table.hpp"

namespace crux {

class GridPotential {
 public:
  GridPotential() = default;
  explicit GridPotential(const QTable& transferred);

  double operator()(StateCode grid_state) const;
  // The shaping term F = gamma phi(s') - phi(s) of a transition.
  double shaping(StateCode grid_state, StateCode next_grid_state, double gamma) const {
    return gamma * (*this)(next_grid_state) - (*this)(grid_state);
  }

 private:
  std::unordered_map<StateCode, double> best_;
};

}  // namespace crux
