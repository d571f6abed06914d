#include "ik/ik_solver.hpp"

#include "body/kinematics.hpp"
#include "body/wall_penetration.hpp"

namespace crux {

IkResult solve_ik(const BodyModel& model, BodyData& data, const Posture& g_init, const ReachTarget& target,
                  const IkParameters& parameters, const PathRecorder& recorder) {
  if (parameters.rule_out_beyond_reach && beyond_reach(model.reach_envelope, target, parameters.tolerances)) {
    forward_kinematics(model, data, g_init);  // as the solvers leave data: the returned posture
    recorder.start(g_init);
    return {.reached = false, .residual_m = grasp_residual(data.points, target), .posture = g_init};
  }
  IkResult result;
  if (parameters.solver == IkSolverKind::Paper) {
    GradientDescentParameters paper = parameters.paper;
    paper.keep_out_of_wall = parameters.wall == WallRule::Avoid;
    result = solve_ik_gradient_descent(model, data, g_init, target, parameters.tolerances, parameters.time_step_s,
                                       paper, recorder);
  } else {
    DampedLeastSquaresParameters fast = parameters.fast;
    fast.keep_out_of_wall = parameters.wall == WallRule::Avoid;
    result = solve_ik_damped_least_squares(model, data, g_init, target, parameters.tolerances, parameters.time_step_s,
                                           fast, recorder);
  }
  // data holds the returned posture, every joint placed.
  if (parameters.wall == WallRule::Reject && result.reached && wall_penetration(model, data).passes_through()) {
    result.reached = false;
    result.posture = g_init;
    forward_kinematics(model, data, g_init);
  }
  return result;
}

}  // namespace crux
