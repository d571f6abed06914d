#pragma once
// Agent-space descriptors (paper, section III-D): a state is the free limb and the tiles
// of the three held holds on the grid placed on the free limb; an action is a tile.
//
// Integer encoding (docs/DESIGN.md): with T tiles, a tile digit is tile + 1, or 0 for a
// hold outside the grid; state = free_limb * (T+1)^3 + d_first * (T+1)^2 +
// d_second * (T+1) + d_third, the held limbs taken in limb order. For the paper's 35
// tiles there are 4 * 36^3 = 186624 state codes and 35 action codes.

#include <array>
#include <cstdint>

#include "agent_space/moving_grid.hpp"
#include "configurations/hold_configuration.hpp"

namespace crux {

struct AgentState {
  Limb free_limb = Limb::RightHand;
  std::array<int, 3> held_tiles{kOutsideGrid, kOutsideGrid, kOutsideGrid};  // held limbs in limb order
  bool operator==(const AgentState&) const = default;
};

// Describes a 3-configuration with the grid placed on its free limb (place_grid).
AgentState describe_state(const Wall& wall, const HoldConfiguration& state, const GridPlacement& placement);

std::uint32_t encode(const AgentState& state, const GridParameters& grid);
AgentState decode_agent_state(std::uint32_t code, const GridParameters& grid);
std::uint32_t agent_state_count(const GridParameters& grid);

}  // namespace crux
