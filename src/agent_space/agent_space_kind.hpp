#pragma once
// Which agent space names holds and states (grid.agent_space; docs/TRANSFER.md): the
// paper's moving grid, or the reach sectors around the free limb's shoulder or hip.

#include "common/enum_names.hpp"

namespace crux {

enum class AgentSpaceKind { Grid, Reach };
template <>
struct EnumNames<AgentSpaceKind> {
  static constexpr std::array<EnumName<AgentSpaceKind>, 2> entries{
      {{AgentSpaceKind::Grid, "grid"}, {AgentSpaceKind::Reach, "reach"}}};
};

// The tile (or cell) of a point that lies in none, in either agent space.
inline constexpr int kOutsideGrid = -1;

}  // namespace crux
