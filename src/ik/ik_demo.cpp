#include "ik/ik_demo.hpp"

#include <chrono>

#include "ik/reach_queries.hpp"

namespace crux {

namespace {

struct DemoQuery {
  const char* description;
  Limb limb;
  Eigen::Vector3d move;  // of the limb's hold, from the start layout
};

}  // namespace

std::vector<IkDemoSolve> run_ik_demo(const BodyModel& model) {
  const DemoQuery queries[] = {
      {"start layout, from standing", Limb::RightHand, Eigen::Vector3d::Zero()},
      {"right hand 0.5 m up", Limb::RightHand, {0, 0, 0.5}},
      {"left hand 0.3 m left and 0.4 m up", Limb::LeftHand, {0, 0.3, 0.4}},
      {"right foot 0.5 m up", Limb::RightFoot, {0, 0, 0.5}},
      {"left hand 3 m up (no body can)", Limb::LeftHand, {0, 0, 3.0}},
  };
  IkParameters settings;
  const Posture start = start_layout_posture(model, settings);
  BodyData data(model);
  std::vector<IkDemoSolve> solves;
  for (const DemoQuery& q : queries) {
    ReachTarget target;
    target.hold_centres = start_layout_holds();
    target.hold_centres[static_cast<int>(q.limb)] += q.move;
    target.root = root_target(model, target.hold_centres);
    const Posture g_init = q.move.isZero() ? standing_posture(target.root) : start;
    for (const IkSolverKind kind : {IkSolverKind::Paper, IkSolverKind::Fast}) {
      settings.solver = kind;
      const auto t0 = std::chrono::steady_clock::now();
      const IkResult result = solve_ik(model, data, g_init, target, settings);
      const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
      solves.push_back({q.description, kind, result, us});
    }
  }
  return solves;
}

}  // namespace crux
