#include "ik/reach_queries.hpp"

#include <algorithm>
#include <cmath>

#include "common/input_error.hpp"
#include "common/random.hpp"

namespace crux {

std::array<Eigen::Vector3d, kLimbCount> start_layout_holds() {
  constexpr double tile_width = 0.3, tile_height = 0.5;
  return {Eigen::Vector3d(0.0, 1 * tile_width, 3 * tile_height), Eigen::Vector3d(0.0, 3 * tile_width, 3 * tile_height),
          Eigen::Vector3d(0.0, 1 * tile_width, 0.0), Eigen::Vector3d(0.0, 3 * tile_width, 0.0)};
}

namespace {

// Climbing-like layouts only: arms and legs uncrossed (y grows to the climber's left)
// and both feet below both hands.
bool natural_layout(const std::array<Eigen::Vector3d, kLimbCount>& h) {
  const auto& rh = h[static_cast<int>(Limb::RightHand)];
  const auto& lh = h[static_cast<int>(Limb::LeftHand)];
  const auto& rf = h[static_cast<int>(Limb::RightFoot)];
  const auto& lf = h[static_cast<int>(Limb::LeftFoot)];
  return rh.y() <= lh.y() && rf.y() <= lf.y() && std::max(rf.z(), lf.z()) < std::min(rh.z(), lh.z());
}

}  // namespace

Posture start_layout_posture(const BodyModel& model, const IkParameters& parameters, const RootTargetParameters& root) {
  ReachTarget target;
  target.hold_centres = start_layout_holds();
  target.root = root_target(model, target.hold_centres, root);
  BodyData data(model);
  const IkResult result = solve_ik(model, data, standing_posture(target.root), target, parameters);
  // The IK's keys decide it (an extreme tolerance or step size): the user's input, not a fault.
  if (!result.reached) {
    throw InputError("ik",
                     "with these ik settings the solver does not reach the start layout from standing, where "
                     "the queries start");
  }
  return result.posture;
}

std::vector<ReachQuery> climbing_reach_queries(const BodyModel& model, const IkParameters& walk_settings, int count,
                                               std::uint64_t seed, const ReachQueryParameters& parameters) {
  Random random(seed);
  BodyData data(model);
  const Posture home = start_layout_posture(model, walk_settings, parameters.root);
  const auto home_holds = start_layout_holds();
  Posture posture = home;
  auto holds = home_holds;
  std::vector<ReachQuery> queries;
  queries.reserve(count);
  for (int n = 0; n < count; ++n) {
    if (parameters.restart_every > 0 && n % parameters.restart_every == 0) {
      posture = home;
      holds = home_holds;
    }
    ReachQuery query;
    query.start = posture;
    query.far_move = random.uniform() < parameters.far_share;
    do {
      query.moved_limb = static_cast<Limb>(random.below(kLimbCount));
      const double distance = query.far_move ? random.uniform(parameters.far_move_min_m, parameters.far_move_max_m)
                                             : parameters.max_move_m * std::sqrt(random.uniform());
      const double angle = random.uniform(0.0, 2.0 * M_PI);
      query.target.hold_centres = holds;
      query.target.hold_centres[static_cast<int>(query.moved_limb)] +=
          Eigen::Vector3d(0.0, distance * std::cos(angle), distance * std::sin(angle));
    } while (!natural_layout(query.target.hold_centres));
    query.target.root = root_target(model, query.target.hold_centres, parameters.root);
    const IkResult result = solve_ik(model, data, posture, query.target, walk_settings);
    if (result.reached) {
      posture = result.posture;
      holds = query.target.hold_centres;
    }
    queries.push_back(query);
  }
  return queries;
}

}  // namespace crux
