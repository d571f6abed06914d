#pragma once
// The one mechanism by which an enum's values get their names in files, flags and
// outputs, and are parsed back: each enum declares, beside itself, a specialisation of
// EnumNames listing every value with its name (and, optionally, a short alias that
// parsing also takes). enum_name, parse_enum and enum_choices follow from it, so a name
// is spelled once.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace crux {

template <typename Enum>
struct EnumName {
  Enum value;
  const char* name;
  const char* alias = nullptr;  // also accepted by parse_enum, never written
};

// Specialised for each named enum with `static constexpr std::array<EnumName<E>, N> entries`.
template <typename Enum>
struct EnumNames;

template <typename Enum>
const char* enum_name(Enum value) {
  for (const auto& entry : EnumNames<Enum>::entries) {
    if (entry.value == value) return entry.name;
  }
  return "?";
}

template <typename Enum>
std::optional<Enum> parse_enum(std::string_view text) {
  for (const auto& entry : EnumNames<Enum>::entries) {
    if (text == entry.name || (entry.alias != nullptr && text == entry.alias)) return entry.value;
  }
  return std::nullopt;
}

// "a, b or c": the names, for help texts and error messages.
template <typename Enum>
std::string enum_choices() {
  const auto& entries = EnumNames<Enum>::entries;
  std::string out;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i > 0) out += i + 1 == entries.size() ? " or " : ", ";
    out += entries[i].name;
  }
  return out;
}

}  // namespace crux
