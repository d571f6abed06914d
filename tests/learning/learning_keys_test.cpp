#include "learning/learning_keys.hpp"

#include <gtest/gtest.h>

#include "support/key_declaration.hpp"

namespace crux {
namespace {

TEST(LearningKeys, DeclaresDynaQsParametersAndItsTransferMode) {
  DynaParameters dyna;
  expect_key_declaration(dyna, [](auto& keys, auto& p) { dyna_keys(keys, p); }, {"learning"});
  expect_key_declaration(dyna, [](auto& keys, auto& p) { transfer_keys(keys, p); }, {"experiment"});
}

TEST(LearningKeys, TheDiscountStopsShortOfOneSoThatValuesStayFinite) {
  DynaParameters dyna;
  std::vector<ConfigField> keys;
  dyna_keys(keys, dyna);
  const Bounds& gamma = declared_field(keys, "learning.gamma").bounds;
  EXPECT_TRUE(gamma.contains(0));
  EXPECT_TRUE(gamma.contains(0.999));
  EXPECT_FALSE(gamma.contains(1));
}

}  // namespace
}  // namespace crux
