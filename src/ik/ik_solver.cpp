#include "ik/ik_solver.hpp"

#include "body/kinematics.hpp"

namespace crux {

const char* ik_solver_name(IkSolverKind kind) { return kind == IkSolverKind::Paper ? "paper" : "fast"; }

std::optional<IkSolverKind> parse_ik_solver(std::string_view name) {
  if (name == "paper") return IkSolverKind::Paper;
  if (name == "fast") return IkSolverKind::Fast;
  return std::nullopt;
}

IkResult solve_ik(const BodyModel& model, BodyData& data, const Posture& g_init, const ReachTarget& target,
                  const IkParameters& settings, const PathRecorder& recorder) {
  if (settings.rule_out_beyond_reach && beyond_reach(model.reach_envelope, target, settings.tolerances)) {
    forward_kinematics(model, data, g_init);  // as the solvers leave data: the returned posture
    recorder.start(g_init);
    return {.reached = false, .residual_m = grasp_residual(data.points, target), .posture = g_init};
  }
  if (settings.solver == IkSolverKind::Paper) {
    return solve_ik_gradient_descent(model, data, g_init, target, settings.tolerances, settings.time_step_s,
                                     settings.paper, recorder);
  }
  return solve_ik_damped_least_squares(model, data, g_init, target, settings.tolerances, settings.time_step_s,
                                       settings.fast, recorder);
}

}  // namespace crux
