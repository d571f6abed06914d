#pragma once
// A count printed with its noun, the noun agreeing with the count: "1 seed", "2 seeds",
// "0 seeds". Every count crux prints beside a noun goes through these, so that none
// reads "1 seeds".

#include <string>
#include <string_view>

#include <fmt/format.h>

namespace crux {

// The noun alone, for a count printed apart from it (a padded column): `singular` for
// exactly 1, else `plural`, or `singular` with an "s" when no plural is given.
inline std::string counted_noun(long long count, std::string_view singular, std::string_view plural = {}) {
  if (count == 1) return std::string(singular);
  return plural.empty() ? std::string(singular) + "s" : std::string(plural);
}

// "1 seed", "3 seeds"; "1 query", "2 queries" with the plural given.
inline std::string counted(long long count, std::string_view singular, std::string_view plural = {}) {
  return fmt::format("{} {}", count, counted_noun(count, singular, plural));
}

}  // namespace crux
