#pragma once
// The wall as the IK sees it when it keeps the body out (ik.wall = avoid; docs/MODEL.md,
// choice C24): one residual per primitive that body/wall_penetration counts and that is
// past the skin margin, its deepest point's x beyond the margin, with that x's gradient.
// Both solvers add them to the task: the body is pushed out of the wall while the hands
// and feet are pulled to their holds, and a posture is reached only once no residual is
// left.

#include <array>

#include "body/body_data.hpp"
#include "body/body_model.hpp"
#include "ik/task_jacobian.hpp"

namespace crux {

// More primitives past the margin than this at once keep only the deepest ones (the
// human has 12 counted primitives): the rows a stacked task holds below the points'.
inline constexpr int kMaxWallRows = kMaxExtraTaskRows;

struct WallClearance {
  int rows = 0;
  std::array<double, kMaxWallRows> excess{};   // m past the skin margin, each > 0
  std::array<Posture, kMaxWallRows> gradient;  // d x / d G of each one's deepest point

  bool clear() const { return rows == 0; }
  std::span<const Posture> gradients() const { return {gradient.data(), static_cast<std::size_t>(rows)}; }
  double cost() const;  // 0.5 x the sum of the squared excesses
};

// At the posture of the last forward_kinematics of `data` (every joint placed).
void wall_clearance(const BodyModel& model, const BodyData& data, WallClearance& out);

}  // namespace crux
