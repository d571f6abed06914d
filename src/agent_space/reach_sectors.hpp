#pragma once
// The reach agent space's cells (docs/TRANSFER.md, "The reach agent space"): a hold is
// named by its direction and distance, in the wall plane, from the free limb's shoulder
// or hip, the base of the limb that must reach it. `sectors` equal sectors of the circle,
// sector 0 starting at +y (towards the climber's left) and turning towards +z (up);
// `rings` rings of `ring_width` m; cell = ring * sectors + sector, or kOutsideGrid beyond
// the last ring. A cell's centre is its middle radius and middle angle.

#include <Eigen/Core>

namespace crux {

struct ReachSectors {
  Eigen::Vector2d base = Eigen::Vector2d::Zero();  // (y, z) of the shoulder or hip
  int sectors = 8;
  int rings = 4;
  double ring_width = 0.3;

  int cell_of(const Eigen::Vector3d& point) const;
  Eigen::Vector3d cell_centre(int cell) const;  // on the wall plane x = 0
};

}  // namespace crux
