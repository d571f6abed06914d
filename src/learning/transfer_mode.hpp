#pragma once
// How a run uses the Q_grid it starts from (docs/TRANSFER.md). Each mode is also the rule
// of that run's control, which starts from an empty Q_grid, so that transfer against
// control measures the transferred values alone.
//   paper:    Algorithm 3: w-greedy on an already taken best Q_wall action, else
//             g-greedy on an already taken best Q_grid action, else a random action.
//   informed: Algorithm 3, but g-greedy passes over the actions Q_wall's own experience
//             in this state has seen fail, and the return of the free limb to the hold
//             it has just left, which goes back to the 4-configuration of the step
//             before (action elimination, Zahavy et al. 2018).
//   prior:    informed, and g-greedy's best is taken among the agent-space actions
//             already taken, so the transferred policy acts in place of many of
//             Algorithm 3's random choices (policy reuse, Fernandez and Veloso 2006).
//   seeded:   an untried Q_wall pair starts at the transferred Q_grid value of its
//             agent-space pair, and the agent is epsilon-greedy on Q_wall (value-function
//             transfer, Taylor, Stone and Liu 2007).
//   shaping:  Algorithm 3, with Q_wall learning from rewards shaped by the potential
//             phi(s) = the best taken value of the transferred Q_grid in grid(s) (potential-based
//             shaping, Ng, Harada and Russell 1999; learnt in agent space as Konidaris
//             and Barto's autonomous shaping, 2006).
//   ordered:  epsilon-greedy on Q_wall as seeded without seeds (an untried pair's 0 is
//             optimistic), with the ties of Q_wall's best value broken by the transferred
//             Q_grid's best taken value: it orders which untried move comes first and never
//             raises a value (learned action priors, Rosman and Ramamoorthy 2012).
//   network:  ordered, with the ties broken by a score of each candidate given from
//             outside (the climber's learnt policy network, experiments/learning_run),
//             the highest first: knowledge learnt once across many walls, no Q_grid.

#include "common/enum_names.hpp"

namespace crux {

enum class TransferMode { Paper, Informed, Prior, Seeded, Shaping, Ordered, Network };
template <>
struct EnumNames<TransferMode> {
  static constexpr std::array<EnumName<TransferMode>, 7> entries{{{TransferMode::Paper, "paper"},
                                                                  {TransferMode::Informed, "informed"},
                                                                  {TransferMode::Prior, "prior"},
                                                                  {TransferMode::Seeded, "seeded"},
                                                                  {TransferMode::Shaping, "shaping"},
                                                                  {TransferMode::Ordered, "ordered"},
                                                                  {TransferMode::Network, "network"}}};
};

}  // namespace crux
