#include "agent_space/agent_descriptor.hpp"

namespace crux {

AgentState describe_state(const Wall& wall, const HoldConfiguration& state, const GridPlacement& placement) {
  AgentState out;
  out.free_limb = state.free_limb();
  int slot = 0;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    if (limb == static_cast<int>(out.free_limb)) continue;
    out.held_tiles[slot++] = placement.tile_of(wall.holds[state.holds[limb]].position);
  }
  return out;
}

std::uint32_t encode(const AgentState& state, const GridParameters& grid) {
  const std::uint32_t base = static_cast<std::uint32_t>(grid.tile_count()) + 1;
  std::uint32_t code = static_cast<std::uint32_t>(state.free_limb);
  for (const int tile : state.held_tiles) code = code * base + static_cast<std::uint32_t>(tile + 1);
  return code;
}

AgentState decode_agent_state(std::uint32_t code, const GridParameters& grid) {
  const std::uint32_t base = static_cast<std::uint32_t>(grid.tile_count()) + 1;
  AgentState state;
  for (int slot = 2; slot >= 0; --slot) {
    state.held_tiles[slot] = static_cast<int>(code % base) - 1;
    code /= base;
  }
  state.free_limb = static_cast<Limb>(code);
  return state;
}

std::uint32_t agent_state_count(const GridParameters& grid) {
  const std::uint32_t base = static_cast<std::uint32_t>(grid.tile_count()) + 1;
  return kLimbCount * base * base * base;
}

}  // namespace crux
