#include "ik/ik_keys.hpp"

#include <gtest/gtest.h>

#include "support/key_declaration.hpp"

namespace crux {
namespace {

TEST(IkKeys, DeclaresTheSolversParametersInTheIkSection) {
  IkParameters ik;
  expect_key_declaration(ik, [](auto& keys, auto& p) { ik_keys(keys, p); }, {"ik"});
}

TEST(IkKeys, AChoiceParsedReachesTheSolversEnum) {
  IkParameters ik;
  std::vector<ConfigField> keys;
  ik_keys(keys, ik);
  const auto& solver = std::get<ChoiceTarget<false>>(declared_field(keys, "ik.solver").target);
  ASSERT_TRUE(solver.type->parse(solver.target, "paper"));
  EXPECT_EQ(ik.solver, IkSolverKind::Paper);
  EXPECT_FALSE(solver.type->parse(solver.target, "slow"));
  EXPECT_EQ(ik.solver, IkSolverKind::Paper);
  // A solve's simulated time step is a positive share of a second.
  EXPECT_FALSE(declared_field(keys, "ik.time_step").bounds.contains(0));
  EXPECT_EQ(declared_field(keys, "ik.time_step").unit, "s");
}

}  // namespace
}  // namespace crux
