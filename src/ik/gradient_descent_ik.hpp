#pragma once
// The paper's IK (section III-B, Algorithm 1): gradient descent on f(E) with the step
// zeroed, joint by joint, where it would pass a limit, stopped by the grasp/root test
// or by the time-out Delta_t of simulated time; on time-out it returns G_init.

#include "body/body_data.hpp"
#include "ik/ik_result.hpp"
#include "ik/reach_target.hpp"

namespace crux {

struct GradientDescentSettings {
  double step_size = 0.25;  // alpha (calibration: docs/DESIGN.md)
  double timeout_s = 5.5;   // Delta_t
  // Iterations that fit in Delta_t at `time_step_s` simulated seconds each.
  int max_iterations(double time_step_s) const;
};

// `time_step_s`: simulated time per iteration (spec item 9: see docs/DESIGN.md).
IkResult solve_ik_gradient_descent(const BodyModel& model, BodyData& data, const Posture& g_init,
                                   const ReachTarget& target, const ReachTolerances& tolerances, double time_step_s,
                                   const GradientDescentSettings& settings, const PathRecorder& recorder = {});

}  // namespace crux
