#pragma once
// The cells of a sweep (crux sweep): every combination of the values of the keys its
// file gives as lists. Cell i picks value digit k of each listed key, the first listed
// key varying slowest, so cells are numbered as nested loops read.

#include <cstddef>
#include <vector>

#include "experiments/experiment_config.hpp"

namespace crux {

struct SweepGrid {
  std::vector<ListedKey> keys;  // in the order of config_fields

  std::size_t cells() const;  // the product of the list lengths; 1 without lists
  ListChoice choice(std::size_t cell) const;
};

}  // namespace crux
