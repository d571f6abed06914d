#pragma once
// The nearest of a list of names to what the user typed, for "did you mean" hints.

#include <algorithm>
#include <string>
#include <vector>

namespace crux::cli {

// Levenshtein distance between two short strings.
inline std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The candidate nearest to `typed` when it is close enough to be a typo (at most a
// fifth of its length, and at least 2, edits away) or the only one it begins; empty
// otherwise.
inline std::string nearest_name(const std::string& typed, const std::vector<std::string>& candidates) {
  std::string best;
  int prefixed = 0;
  for (const std::string& candidate : candidates) {
    if (!typed.empty() && candidate.rfind(typed, 0) == 0) best = candidate, ++prefixed;
  }
  if (prefixed == 1) return best;
  best.clear();
  std::size_t best_distance = std::max<std::size_t>(2, typed.size() / 5) + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t d = edit_distance(typed, candidate);
    if (d < best_distance) best = candidate, best_distance = d;
  }
  return best;
}

}  // namespace crux::cli
