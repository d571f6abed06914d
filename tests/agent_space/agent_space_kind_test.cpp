#include "agent_space/agent_space_kind.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(AgentSpaceKind, NamesRoundTripAndUnknownNamesAreNone) {
  for (const AgentSpaceKind kind : {AgentSpaceKind::Grid, AgentSpaceKind::Reach}) {
    EXPECT_EQ(parse_agent_space(agent_space_name(kind)), kind);
  }
  EXPECT_STREQ(agent_space_name(AgentSpaceKind::Grid), "grid");
  EXPECT_STREQ(agent_space_name(AgentSpaceKind::Reach), "reach");
  EXPECT_EQ(parse_agent_space("Grid"), std::nullopt);
  EXPECT_EQ(parse_agent_space(""), std::nullopt);
}

}  // namespace
}  // namespace crux
