#include "sweeps/sweep_grid.hpp"

namespace crux {

std::size_t SweepGrid::cells() const {
  std::size_t product = 1;
  for (const ListedKey& key : keys) product *= key.values;
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
