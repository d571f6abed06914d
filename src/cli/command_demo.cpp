// crux demo: load the body and solve a few reaching queries with both solvers.

#include <chrono>
#include <iostream>
#include <memory>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "experiments/run_inputs.hpp"
#include "ik/ik_solver.hpp"
#include "ik/reach_queries.hpp"

namespace crux::cli {

namespace {

struct DemoQuery {
  const char* description;
  Limb limb;
  Eigen::Vector3d move;  // of the limb's hold, from the start layout
};

void run_demo(const ExperimentConfig& config, bool json) {
  const BodyModel model = load_configured_body(config);
  const DemoQuery queries[] = {
      {"start layout, from standing", Limb::RightHand, Eigen::Vector3d::Zero()},
      {"right hand 0.5 m up", Limb::RightHand, {0, 0, 0.5}},
      {"left hand 0.3 m left and 0.4 m up", Limb::LeftHand, {0, 0.3, 0.4}},
      {"right foot 0.5 m up", Limb::RightFoot, {0, 0, 0.5}},
      {"left hand 3 m up (no body can)", Limb::LeftHand, {0, 0, 3.0}},
  };
  IkSettings settings;
  const Posture start = start_layout_posture(model, settings);
  BodyData data(model);
  nlohmann::ordered_json out = nlohmann::json::array();
  if (!json) {
    std::cout << fmt::format("body '{}': {} root + {} revolute degrees of freedom, {:.2f} m, {:.1f} kg\n", model.name,
                             kRootDof, kRevoluteDof, model.stature, model.total_mass);
  }
  for (const DemoQuery& q : queries) {
    ReachTarget target;
    target.hold_centres = start_layout_holds();
    target.hold_centres[static_cast<int>(q.limb)] += q.move;
    target.root = root_target(model, target.hold_centres);
    const bool from_standing = q.move.isZero();
    const Posture g_init = from_standing ? standing_posture(target.root) : start;
    if (!json) std::cout << fmt::format("\n{}:\n", q.description);
    for (const IkSolverKind kind : {IkSolverKind::Paper, IkSolverKind::Fast}) {
      settings.solver = kind;
      const auto t0 = std::chrono::steady_clock::now();
      const IkResult r = solve_ik(model, data, g_init, target, settings);
      const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
      if (json) {
        out.push_back({{"query", q.description}, {"solver", ik_solver_name(kind)}, {"reached", r.reached},
                       {"iterations", r.iterations}, {"simulated_time_s", r.simulated_time_s},
                       {"residual_m", r.residual_m}, {"wall_clock_us", us}});
      } else {
        std::cout << fmt::format("  {:<5} {:<11} {:5d} iterations, {:5.2f} s simulated, residual {:.3f} m, {:8.1f} us\n",
                                 ik_solver_name(kind), r.reached ? "reached" : "NOT reached", r.iterations,
                                 r.simulated_time_s, r.residual_m, us);
      }
    }
  }
  if (json) std::cout << out.dump(2) << '\n';
}

}  // namespace

void add_demo_command(CLI::App& app) {
  auto* command = app.add_subcommand("demo", "Load the body and solve a few reaching queries with both IK solvers");
  auto binding = std::make_shared<ParameterBinding>("demo", ParameterSet{{"experiment.urdf"}, {}});
  auto json = std::make_shared<bool>(false);
  binding->bind(command);
  command->add_flag("--json", *json, "Print JSON instead of text");
  command->callback([binding, json] { run_demo(binding->resolve(), *json); });
}

}  // namespace crux::cli
