#include "ik/ik_path.hpp"

#include <algorithm>

#include "body/kinematics.hpp"

namespace crux {

void ik_path_samples(const BodyModel& model, BodyData& data, const Posture& from, const Posture& to,
                     const ReachTarget& target, const IkParameters& ik, int count, std::vector<Posture>& path,
                     std::vector<Posture>& samples) {
  IkParameters paper = ik;
  paper.solver = IkSolverKind::Paper;
  forward_kinematics(model, data, from);
  // The gradient descent would wander off a posture that already grasps the target and
  // come back.
  if (target_reached(data.points, target, paper.tolerances)) {
    path.assign(1, from);
  } else {
    solve_ik(model, data, from, target, paper, PathRecorder{&path, 1});
  }
  // Equal joint-space distances along the path (the solver's first iterates move far
  // more than its last), joined linearly to `to`.
  samples.clear();
  std::vector<double> distance(path.size(), 0.0);
  for (std::size_t i = 1; i < path.size(); ++i) distance[i] = distance[i - 1] + (path[i] - path[i - 1]).norm();
  std::size_t segment = 1;
  for (int f = 1; f <= count; ++f) {
    const double fraction = static_cast<double>(f) / count;
    Posture on_path = path.back();
    if (distance.back() > 0) {
      const double wanted = fraction * distance.back();
      while (segment + 1 < path.size() && distance[segment] < wanted) ++segment;
      const double length = distance[segment] - distance[segment - 1];
      const double t = length > 0 ? std::clamp((wanted - distance[segment - 1]) / length, 0.0, 1.0) : 1.0;
      on_path = (1 - t) * path[segment - 1] + t * path[segment];
    }
    samples.push_back((1 - fraction) * on_path + fraction * to);
  }
}

}  // namespace crux
