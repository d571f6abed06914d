#include "sweeps/sweep_grid.hpp"

#include <fmt/format.h>

#include "common/input_error.hpp"

namespace crux {

std::size_t SweepGrid::cells() const {
  std::size_t product = 1;
  for (const ListedKey& key : keys) {
    // Both factors are at most kMaxSweepCells here, so the product cannot overflow.
    if (key.values <= kMaxSweepCells) product *= key.values;
    if (key.values > kMaxSweepCells || product > kMaxSweepCells) {
      throw InputError(source, fmt::format("its lists make more than {} cells (the product of their lengths), the "
                                           "most a sweep may have",
                                           kMaxSweepCells));
    }
  }
  return product;
}

ListChoice SweepGrid::choice(std::size_t cell) const {
  ListChoice choice;
  for (std::size_t k = keys.size(); k-- > 0;) {
    choice[keys[k].key] = cell % keys[k].values;
    cell /= keys[k].values;
  }
  return choice;
}

}  // namespace crux
