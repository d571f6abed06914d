#pragma once
// crux's fast IK: Levenberg-Marquardt (adaptively damped least squares). By default it
// minimises the paper's f(E); with a positive aim fraction each operational point is
// pulled only to the nearest point of a sphere inside its tolerance sphere, so that it
// seeks any posture the termination test accepts (docs/DESIGN.md compares both). Joint limits are handled by an active
// set (a joint at a limit and pushed past it is frozen for the step) and by projection. Same inputs, outputs and
// termination test as Algorithm 1; it gives up early when the cost stops decreasing,
// which is what makes unreachable queries cheap.

#include "body/body_data.hpp"
#include "ik/ik_result.hpp"
#include "ik/reach_target.hpp"

namespace crux {

struct DampedLeastSquaresParameters {
  int max_iterations = 100;
  // Radius aimed at, as a share of each tolerance radius (grasp contact, root sphere).
  double aim_fraction = 0.0;
  double initial_damping = 1e-2;  // lambda, in m^2
  double min_damping = 1e-6;
  double max_damping = 1e3;  // beyond this no step lowers f: a local minimum
  // Stop when `stall_iterations` steps in a row each lower f by less than this share.
  double stall_relative_decrease = 1e-3;
  int stall_iterations = 3;
  // Keep the body out of the wall (ik.wall = avoid): the wall's residuals join the task
  // as rows of their own, and a posture is reached only once they are all zero
  // (ik/wall_clearance.hpp).
  bool keep_out_of_wall = false;
};

// `time_step_s`: simulated time charged per linearisation, as per iteration of Algorithm 1.
IkResult solve_ik_damped_least_squares(const BodyModel& model, BodyData& data, const Posture& g_init,
                                       const ReachTarget& target, const ReachTolerances& tolerances, double time_step_s,
                                       const DampedLeastSquaresParameters& parameters,
                                       const PathRecorder& recorder = {});

}  // namespace crux
