#include "wall/wall.hpp"

namespace crux {

int Wall::index_of(int id) const {
  for (int i = 0; i < hold_count(); ++i) {
    if (holds[i].id == id) return i;
  }
  return -1;
}

}  // namespace crux
