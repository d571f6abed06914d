#pragma once
// The cells of a sweep (crux sweep): every combination of the values of the keys its
// file gives as lists. Cell i picks value digit k of each listed key, the first listed
// key varying slowest, so cells are numbered as nested loops read.

#include <cstddef>
#include <string>
#include <vector>

#include "experiments/experiment_config.hpp"

namespace crux {

// The most cells a sweep may have. Each cell is at least three learning runs of
// experiment.iterations (8000 in the paper) and keeps its config in memory while the
// sweep runs (~2.4 kB): 100000 cells are months of computing and ~250 MB.
inline constexpr std::size_t kMaxSweepCells = 100000;

struct SweepGrid {
  std::vector<ListedKey> keys;  // in the order of config_fields
  std::string source{};         // the sweep file, named in errors

  // The product of the list lengths; 1 without lists. InputError(source) beyond
  // kMaxSweepCells, told before the product could overflow.
  std::size_t cells() const;
  ListChoice choice(std::size_t cell) const;
};

}  // namespace crux
