#pragma once
// How one configuration key is declared: its name ("section.name"), help, the field it
// sets (typed: an enum is a choice parsed into the enum itself), unit and bounds. Each
// layer declares the keys of its own parameter structs beside them with these types
// (ik/ik_keys, learning/learning_keys, ...), and experiments/experiment_config gathers
// them into the table that flags, TOML, Python and config.toml's comments all come from.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "common/enum_names.hpp"

namespace crux {

// The values a number key takes. An integer key's bounds are integers. Each bound keeps
// every computation that uses the key finite and its time bounded; `why` says what the
// bound comes from.
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  // min itself excluded
  bool max_open = false;
  const char* why = nullptr;  // appended to the refusal, in parentheses
  // The key sizes the work (iterations, walls, threads, resamples, cells): its maximum is
  // accepted but may take hours, so a test of the bounds checks it without running it.
  bool sizes_work = false;

  bool contains(double value) const;
  // "> 0", ">= 0", "0 to 1", "[0, 1)": for --help and config.toml's comments.
  std::string summary(bool integer) const;
  // "must be positive", "must be from 1 to 64", "must be in [0, 1)".
  std::string problem(bool integer) const;
};
inline constexpr Bounds kAnyNumber{};
inline constexpr Bounds kPositive{.min = 0, .min_open = true};
inline constexpr Bounds kNonNegative{.min = 0};
constexpr Bounds closed_range(double min, double max, const char* why = nullptr) {
  return {.min = min, .max = max, .why = why};
}
// A count that sizes the work, from `min` to `max`.
constexpr Bounds work_size(double min, double max, const char* why = nullptr) {
  return {.min = min, .max = max, .why = why, .sizes_work = true};
}

// How a choice key's text and its enum meet: the enum's EnumNames, or a list of its own
// (physics.strength's climbing levels, whose empty text means unset).
struct ChoiceType {
  std::string (*text)(const void* target);             // "" when unset
  bool (*parse)(void* target, std::string_view text);  // false: not a choice
  std::string (*choices)();                            // "a, b or c"
};
template <typename Enum>
const ChoiceType& enum_choice_type() {
  static constexpr ChoiceType type{
      [](const void* target) { return std::string(enum_name(*static_cast<const Enum*>(target))); },
      [](void* target, std::string_view text) {
        const auto value = parse_enum<Enum>(text);
        if (value) *static_cast<Enum*>(target) = *value;
        return value.has_value();
      },
      [] { return enum_choices<Enum>(); }};
  return type;
}
template <bool Const>
struct ChoiceTarget {
  std::conditional_t<Const, const void*, void*> target;
  const ChoiceType* type;
};

template <bool Const>
struct ConfigFieldOf {
  template <typename T>
  using Ref = std::conditional_t<Const, const T*, T*>;
  using Target =
      std::variant<Ref<double>, Ref<std::optional<double>>, Ref<int>, Ref<std::optional<int>>, Ref<std::uint64_t>,
                   Ref<std::optional<std::uint64_t>>, Ref<bool>, Ref<std::string>, ChoiceTarget<Const>>;
  std::string key;  // TOML "section.name"
  std::string help;
  Target target;
  std::string unit = {};  // "m", "N", "degrees", "s"; empty for a count or a ratio
  Bounds bounds = {};     // numbers only
  bool is_path = false;   // a file, written absolute so that the config replays from anywhere
  // Written to config.toml: false for presentation only (output.*), which changes no
  // result, so that an output folder's bytes do not depend on how its run was shown.
  bool recorded = true;

  // "number", "integer", "seed", "boolean", "text", "path" or "choice".
  const char* type_name() const;
  bool is_integer() const;
  // The help with the unit, bounds or choices: what --help and config.toml show.
  std::string described_help() const;
};
using ConfigField = ConfigFieldOf<false>;
using ConstConfigField = ConfigFieldOf<true>;

// The fields a declaration appends to: mutable for readers, const for writers.
template <typename Parameters>
using FieldsFor = std::vector<ConfigFieldOf<std::is_const_v<Parameters>>>;

// A choice field over `target`, an enum with EnumNames (mutable or const).
template <typename Enum>
ChoiceTarget<false> choice_of(Enum* target) {
  return {target, &enum_choice_type<Enum>()};
}
template <typename Enum>
ChoiceTarget<true> choice_of(const Enum* target) {
  return {target, &enum_choice_type<Enum>()};
}

// Bounds shared by several layers' keys.
// A length on the wall or the body: beyond 100 m no limb (0.8 m) or wall of holds means
// anything, and the views scale what they draw to it.
inline constexpr double kMaxLengthM = 100;
inline constexpr Bounds kLength{.min = 0, .max = kMaxLengthM, .min_open = true};
inline constexpr Bounds kUnitInterval{.min = 0, .max = 1};
inline constexpr Bounds kAboveZeroToOne{.min = 0, .max = 1, .min_open = true};
inline constexpr Bounds kZeroToBelowOne{.min = 0, .max = 1, .max_open = true};
inline constexpr Bounds kShareOfOne = closed_range(0, 1, "a share");
// A tile of the agent space or of a random wall: from 1 cm (a hold's size) to 10 m (four
// times the body's span).
inline constexpr Bounds kTileSize = closed_range(0.01, 10, "from a hold's size to four times the body's span");

}  // namespace crux
