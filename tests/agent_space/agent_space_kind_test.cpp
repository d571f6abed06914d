#include "agent_space/agent_space_kind.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(AgentSpaceKind, NamesRoundTripAndUnknownNamesAreNone) {
  for (const AgentSpaceKind kind : {AgentSpaceKind::Grid, AgentSpaceKind::Reach}) {
    EXPECT_EQ(parse_enum<AgentSpaceKind>(enum_name(kind)), kind);
  }
  EXPECT_STREQ(enum_name(AgentSpaceKind::Grid), "grid");
  EXPECT_STREQ(enum_name(AgentSpaceKind::Reach), "reach");
  EXPECT_EQ(parse_enum<AgentSpaceKind>("Grid"), std::nullopt);
  EXPECT_EQ(parse_enum<AgentSpaceKind>(""), std::nullopt);
}

}  // namespace
}  // namespace crux
