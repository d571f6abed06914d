#pragma once
// The paper's IK (section III-B, Algorithm 1): gradient descent on f(E) with the step
// zeroed, joint by joint, where it would pass a limit, stopped by the grasp/root test
// or by the time-out Delta_t of simulated time; on time-out it returns G_init.
//
// crux adds one exit that Algorithm 1 does not have: the descent gives up before the
// time-out once it has stalled outside the tolerance (f fell by less than a small share
// over the last few steps while a point is still well outside its sphere). Such a
// descent converges to a local minimum that fails the test, so the verdict is the
// time-out's; on 4000 climbing-like queries the two verdicts never differed and a
// query that reaches is never stopped (docs/DESIGN.md, "The paper's solver"). A
// window of 0 turns it off.

#include "body/body_data.hpp"
#include "ik/ik_result.hpp"
#include "ik/reach_target.hpp"

namespace crux {

struct GradientDescentParameters {
  double step_size = 0.25;  // alpha (calibration: docs/DESIGN.md)
  double timeout_s = 5.5;   // Delta_t
  // The stall exit: f fell by less than `stall_decrease` x f over the last
  // `stall_iterations` steps while a point is more than `stall_margin_m` outside its sphere.
  int stall_iterations = 10;
  double stall_decrease = 3e-4;
  double stall_margin_m = 0.10;
  // Keep the body out of the wall (ik.wall = avoid): the wall's residuals join f, and a
  // posture is reached only once they are all zero (ik/wall_clearance.hpp).
  bool keep_out_of_wall = false;
  // Iterations that fit in Delta_t at `time_step_s` simulated seconds each.
  int max_iterations(double time_step_s) const;
};

// `time_step_s`: simulated time per iteration (docs/MODEL.md, choice C9).
IkResult solve_ik_gradient_descent(const BodyModel& model, BodyData& data, const Posture& g_init,
                                   const ReachTarget& target, const ReachTolerances& tolerances, double time_step_s,
                                   const GradientDescentParameters& parameters, const PathRecorder& recorder = {});

}  // namespace crux
