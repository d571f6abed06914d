#pragma once
// The checks every layer's key declaration passes (tests/<layer>/*_keys_test.cpp): the
// mutable and const declarations list the same keys in the same order, each key once, in
// the layer's sections, with help; each sets a member of the parameters it is declared
// over (its address lies inside them); each number's default lies within its bounds; and
// each choice's default is written as a name that parses back.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "common/config_field.hpp"

namespace crux {

inline const void* declared_target(const ConfigField& field) {
  return std::visit(
      [](auto target) -> const void* {
        if constexpr (std::is_same_v<decltype(target), ChoiceTarget<false>>) {
          return target.target;
        } else {
          return target;
        }
      },
      field.target);
}

// `declare(keys, parameters)` over a mutable and a const `parameters`; the keys of `outside`
// set something other than `parameters` (physics.strength: a level's name).
template <typename Parameters, typename Declare>
void expect_key_declaration(Parameters& parameters, Declare declare, const std::set<std::string>& sections,
                            const std::set<std::string>& outside = {}) {
  std::vector<ConfigField> fields;
  declare(fields, parameters);
  std::vector<ConstConfigField> const_fields;
  declare(const_fields, std::as_const(parameters));
  ASSERT_FALSE(fields.empty());
  ASSERT_EQ(fields.size(), const_fields.size());
  std::set<std::string> seen;
  const auto* begin = reinterpret_cast<const char*>(&parameters);
  const auto* end = reinterpret_cast<const char*>(&parameters + 1);
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const ConfigField& field = fields[i];
    SCOPED_TRACE(field.key);
    EXPECT_EQ(field.key, const_fields[i].key);
    EXPECT_TRUE(seen.insert(field.key).second) << "declared twice";
    EXPECT_TRUE(sections.count(field.key.substr(0, field.key.find('.'))) == 1) << "outside the layer's sections";
    EXPECT_FALSE(field.help.empty());
    const auto* target = static_cast<const char*>(declared_target(field));
    EXPECT_EQ(target >= begin && target < end, outside.count(field.key) == 0) << "sets a member of another struct";
    std::visit(
        [&](auto target) {
          using T = std::remove_pointer_t<decltype(target)>;
          if constexpr (std::is_same_v<T, double> || std::is_same_v<T, int>) {
            EXPECT_TRUE(field.bounds.contains(*target)) << "default " << *target;
          } else if constexpr (std::is_same_v<T, std::optional<double>> || std::is_same_v<T, std::optional<int>>) {
            if (*target) {
              EXPECT_TRUE(field.bounds.contains(**target)) << "default " << **target;
            }
          } else if constexpr (std::is_same_v<decltype(target), ChoiceTarget<false>>) {
            const std::string name = target.type->text(target.target);
            if (!name.empty()) {
              EXPECT_TRUE(target.type->parse(target.target, name)) << name;
              EXPECT_EQ(target.type->text(target.target), name);
            }
          }
        },
        field.target);
  }
}

// The field of `key` in `fields`; fails the test when there is none.
inline const ConfigField& declared_field(const std::vector<ConfigField>& fields, const std::string& key) {
  for (const ConfigField& field : fields) {
    if (field.key == key) return field;
  }
  ADD_FAILURE() << key << " is not declared";
  static const ConfigField none{};
  return none;
}

}  // namespace crux
