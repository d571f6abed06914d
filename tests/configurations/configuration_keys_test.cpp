#include "configurations/configuration_keys.hpp"

#include <gtest/gtest.h>

#include "support/key_declaration.hpp"

namespace crux {
namespace {

TEST(ConfigurationKeys, ReachabilityDeclaresTheIkSectionWithTheSolversKeysFirst) {
  ReachabilityParameters reachability;
  expect_key_declaration(reachability, [](auto& keys, auto& p) { reachability_keys(keys, p); }, {"ik"});
  std::vector<ConfigField> keys;
  reachability_keys(keys, reachability);
  EXPECT_EQ(keys.front().key, "ik.solver");
  EXPECT_EQ(keys.back().key, "ik.guess");
  *std::get<double*>(declared_field(keys, "ik.wall_distance").target) = 0.4;
  EXPECT_EQ(reachability.root.distance_from_wall, 0.4);
}

TEST(ConfigurationKeys, FilterDeclaresTheFilterSection) {
  FilterParameters filter;
  expect_key_declaration(filter, [](auto& keys, auto& p) { filter_keys(keys, p); }, {"filter"});
}

}  // namespace
}  // namespace crux
