#pragma once
// The immutable climbing wall (paper, section III-A): hold spheres in the wall plane,
// the start configuration and the finishing height. Any layout is allowed, not only
// the paper's grid.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "body/limb.hpp"

namespace crux {

struct Hold {
  int id = 0;  // positive and unique within a wall; 0 means "no hold" in configurations
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double radius = 0.04;
  // The direction in which the hold can push on a hand or foot (unit, wall coordinates);
  // unset: the contact model's default. Wall files of version 2 carry it.
  std::optional<Eigen::Vector3d> support{};
};

// A configuration code holds four hold indices in base (holds + 1) within 64 bits, and
// the filter and planner scan holds per state: 10000 keeps both far inside their limits.
constexpr int kMaxHoldCount = 10000;

struct Wall {
  std::string name;
  std::vector<Hold> holds;
  // Hold indices (into `holds`) of the start configuration, limb order.
  std::array<int, kLimbCount> start{0, 0, 0, 0};
  double finish_height = 3.0;  // the episode ends when the centre of mass reaches it (docs/DESIGN.md)
  // Degrees from vertical: > 0 overhanging, < 0 slab (docs/MODEL.md, choice C25). Holds,
  // the body and the finishing height stay in wall coordinates; gravity turns.
  double incline_deg = 0.0;

  int hold_count() const { return static_cast<int>(holds.size()); }
  // Index of the hold with this id, or -1.
  int index_of(int id) const;
};

}  // namespace crux
