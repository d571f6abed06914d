#pragma once
// Small walls written inline for tests.

#include <initializer_list>
#include <utility>

#include "wall/wall.hpp"

namespace crux::testing {

// Holds at (y, z) on the wall plane, ids 1.. in order, start = the given indices.
inline Wall wall_with_holds(std::initializer_list<std::pair<double, double>> positions,
                            std::array<int, kLimbCount> start = {0, 1, 2, 3}) {
  Wall wall;
  wall.name = "test wall";
  int id = 1;
  for (const auto& [y, z] : positions) wall.holds.push_back({id++, Eigen::Vector3d(0.0, y, z), 0.04});
  wall.start = start;
  return wall;
}

// A regular layout of columns x rows holds, spacing (dy, dz), ids row by row.
inline Wall grid_wall(int columns, int rows, double dy, double dz) {
  Wall wall;
  wall.name = "grid wall";
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      wall.holds.push_back({r * columns + c + 1, Eigen::Vector3d(0.0, c * dy, r * dz), 0.04});
    }
  }
  wall.start = {3 * columns + 1, 3 * columns + 3, 1, 3};
  return wall;
}

}  // namespace crux::testing
