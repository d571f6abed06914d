#include "body/body_model.hpp"

namespace crux {

Posture standing_posture(const Eigen::Vector3d& root) {
  Posture g = Posture::Zero();
  g.head<kRootDof>() = root;
  return g;
}

bool within_limits(const BodyModel& model, const Posture& g) {
  return ((g.array() >= model.lower_limits.array()) && (g.array() <= model.upper_limits.array())).all();
}

}  // namespace crux
