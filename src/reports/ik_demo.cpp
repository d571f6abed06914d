#include "reports/ik_demo.hpp"

#include <chrono>

#include <fmt/format.h>

#include "common/counted.hpp"
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

nlohmann::ordered_json ik_demo_json(const std::vector<IkDemoSolve>& solves) {
  nlohmann::ordered_json out = nlohmann::json::array();
  for (const IkDemoSolve& s : solves) {
    out.push_back({{"query", s.query},
                   {"solver", enum_name(s.solver)},
                   {"reached", s.result.reached},
                   {"iterations", s.result.iterations},
                   {"simulated_time_s", s.result.simulated_time_s},
                   {"residual_m", s.result.residual_m},
                   {"wall_clock_us", s.wall_clock_us}});
  }
  return out;
}

std::string ik_demo_text(const BodyModel& model, const std::vector<IkDemoSolve>& solves) {
  std::string out = fmt::format("body '{}': {} root + {} revolute degrees of freedom, {:.2f} m, {:.1f} kg\n",
                                model.name, kRootDof, kRevoluteDof, model.stature, model.total_mass);
  for (std::size_t i = 0; i < solves.size(); ++i) {
    const IkDemoSolve& s = solves[i];
    if (i == 0 || solves[i - 1].query != s.query) out += fmt::format("\n{}:\n", s.query);
    out += fmt::format("  {:<5} {:<11} {:5d} {}, {:5.2f} s simulated, residual {:.3f} m, {:8.1f} us\n",
                       enum_name(s.solver), s.result.reached ? "reached" : "NOT reached", s.result.iterations,
                       counted_noun(s.result.iterations, "iteration"), s.result.simulated_time_s, s.result.residual_m,
                       s.wall_clock_us);
  }
  return out;
}

}  // namespace crux
