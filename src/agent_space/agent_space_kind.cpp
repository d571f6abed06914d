#include "agent_space/agent_space_kind.hpp"

namespace crux {

const char* agent_space_name(AgentSpaceKind kind) {
  switch (kind) {
    case AgentSpaceKind::Grid:
      return "grid";
    case AgentSpaceKind::Reach:
      return "reach";
  }
  return "?";
}

std::optional<AgentSpaceKind> parse_agent_space(std::string_view name) {
  for (const AgentSpaceKind kind : {AgentSpaceKind::Grid, AgentSpaceKind::Reach}) {
    if (name == agent_space_name(kind)) return kind;
  }
  return std::nullopt;
}

const char* agent_space_names() { return "grid or reach"; }

}  // namespace crux
