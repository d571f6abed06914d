#pragma once
// Which agent space names holds and states (grid.agent_space; docs/TRANSFER.md): the
// paper's moving grid, or the reach sectors around the free limb's shoulder or hip.

#include <optional>
#include <string_view>

namespace crux {

enum class AgentSpaceKind { Grid, Reach };

const char* agent_space_name(AgentSpaceKind kind);
std::optional<AgentSpaceKind> parse_agent_space(std::string_view name);
const char* agent_space_names();  // for error messages

}  // namespace crux
