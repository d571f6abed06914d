#include "ik/damped_least_squares_ik.hpp"

#include <optional>

#include <Eigen/Cholesky>

#include "body/kinematics.hpp"
#include "ik/task_jacobian.hpp"
#include "ik/wall_clearance.hpp"

namespace crux {

namespace {

// Each operational point aims at the nearest point of a sphere around its target whose
// radius is `aim_fraction` of the termination test's radius: a point already inside
// exerts no pull, so the solver seeks the feasible set that the termination test
// accepts rather than the exact centres, where five conflicting pulls may balance just
// outside it.
void task_error(const BodyData& data, const ReachTarget& target, const ReachTolerances& tolerances, double aim_fraction,
                TaskVector& error) {
  for (int k = 0; k < kOperationalPointCount; ++k) {
    const Eigen::Vector3d offset = data.points[k] - (k == 0 ? target.root : target.hold_centres[k - 1]);
    const double radius =
        aim_fraction * (k == 0 ? tolerances.root_radius : tolerances.grasp_radius + target.hold_radii[k - 1]);
    const double distance = offset.norm();
    error.segment<3>(3 * k) =
        distance > radius ? Eigen::Vector3d(offset * (1.0 - radius / distance)) : Eigen::Vector3d::Zero();
  }
}

// The task error with the wall's excesses below the five points' errors.
void stack_wall_error(const WallClearance& clearance, const TaskVector& error, StackedTaskVector& stacked) {
  stacked.resize(kTaskSize + clearance.rows);
  stacked.head<kTaskSize>() = error;
  for (int r = 0; r < clearance.rows; ++r) stacked[kTaskSize + r] = clearance.excess[r];
}

// The solver's state apart from g and the damping, made once per solve and reused by every
// iteration and trial, so that the hot loop allocates nothing.
struct DlsWorkspace {
  TaskVector error, trial_error;
  TaskMatrix normal;
  Posture trial, gradient, step;
  WallClearance clearance, trial_clearance;
  StackedTaskVector wall_error;
  StackedTaskMatrix wall_normal;
  // g's stacked task: its rows stay g's while the trials move data's points only.
  std::optional<StackedTask> wall_task;
  CoordinateSet frozen = 0;
};

// The task at g, whose Jacobians data holds after this: the gradient, the joints it
// freezes and the normal matrix (with the wall, the stacked task's).
void dls_linearise(const BodyModel& model, BodyData& data, const ChainCoordinates& chains, const Posture& g, bool wall,
                   DlsWorkspace& w) {
  operational_jacobians(model, data);
  task_transpose_product(data, chains, 0, w.error, w.gradient);
  for (int r = 0; wall && r < w.clearance.rows; ++r) w.gradient += w.clearance.excess[r] * w.clearance.gradient[r];
  // Active set: a joint at a limit whose descent direction points out of range is
  // frozen for this step, so the remaining joints absorb the motion.
  w.frozen = 0;
  for (int i = kRootDof; i < kConfigurationDof; ++i) {
    if ((g[i] <= model.lower_limits[i] && w.gradient[i] > 0.0) ||
        (g[i] >= model.upper_limits[i] && w.gradient[i] < 0.0)) {
      w.frozen |= CoordinateSet{1} << i;
    }
  }
  if (wall) {
    stack_wall_error(w.clearance, w.error, w.wall_error);
    w.wall_task.emplace(data, chains, w.clearance.gradients(), w.frozen);
    w.wall_task->normal_matrix(w.wall_normal);
  } else {
    task_normal_matrix(data, chains, w.frozen, w.normal);
  }
}

// w.step: the least-squares step of g's task with `damping` added to the normal matrix's
// diagonal.
void dls_step(const BodyData& data, const ChainCoordinates& chains, bool wall, double damping, DlsWorkspace& w) {
  if (wall) {
    StackedTaskMatrix damped = w.wall_normal;
    damped.diagonal().array() += damping;
    const Eigen::LLT<Eigen::Ref<StackedTaskMatrix>> factor(damped);  // in place, as below
    w.wall_task->transpose_product(factor.solve(w.wall_error), w.step);
  } else {
    TaskMatrix damped = w.normal;
    damped.diagonal().array() += damping;
    // Factorised in place: the same numbers, one copy of the matrix fewer.
    const Eigen::LLT<Eigen::Ref<TaskMatrix>> factor(damped);
    // data.jacobians are still g's: forward kinematics of a trial moves points only.
    task_transpose_product(data, chains, w.frozen, factor.solve(w.error), w.step);
  }
}

// The cost of w.trial, g less the step within the joint limits, whose error goes to
// w.trial_error (and, with the wall, its clearance to w.trial_clearance).
double dls_trial_cost(const BodyModel& model, BodyData& data, const ReachTarget& target,
                      const ReachTolerances& tolerances, double aim_fraction, bool wall, const Posture& g, double cost,
                      DlsWorkspace& w) {
  w.trial = g - w.step;
  w.trial = w.trial.cwiseMax(model.lower_limits).cwiseMin(model.upper_limits);
  operational_forward_kinematics(model, data, w.trial);
  task_error(data, target, tolerances, aim_fraction, w.trial_error);
  double trial_cost = 0.5 * w.trial_error.squaredNorm();
  // The wall's term is never negative: a trial whose points alone cost no less than g
  // is refused without placing the rest of the body.
  if (wall && trial_cost < cost) {
    remaining_forward_kinematics(model, data, w.trial);
    wall_clearance(model, data, w.trial_clearance);
    trial_cost += w.trial_clearance.cost();
  }
  return trial_cost;
}

}  // namespace

IkResult solve_ik_damped_least_squares(const BodyModel& model, BodyData& data, const Posture& g_init,
                                       const ReachTarget& target, const ReachTolerances& tolerances, double time_step_s,
                                       const DampedLeastSquaresParameters& parameters, const PathRecorder& recorder) {
  DlsWorkspace w;
  Posture g = g_init;
  const ChainCoordinates chains = chain_coordinates(model);
  // With the wall, every joint is placed (the head and neck are no operational point's),
  // and the step solves the stacked task of ik/wall_clearance.hpp.
  const bool wall = parameters.keep_out_of_wall;
  const auto place = [&](const Posture& posture, WallClearance& out) {
    if (!wall) return operational_forward_kinematics(model, data, posture);
    forward_kinematics(model, data, posture);
    wall_clearance(model, data, out);
  };

  place(g, w.clearance);
  recorder.start(g);
  task_error(data, target, tolerances, parameters.aim_fraction, w.error);
  double cost = 0.5 * w.error.squaredNorm() + (wall ? w.clearance.cost() : 0.0);
  double damping = parameters.initial_damping;
  int iteration = 0, stalled = 0;
  bool reached = target_reached(data.points, target, tolerances) && (!wall || w.clearance.clear());
  while (!reached && iteration < parameters.max_iterations && stalled < parameters.stall_iterations) {
    ++iteration;
    dls_linearise(model, data, chains, g, wall, w);
    bool improved = false;
    double trial_cost = cost;
    while (damping <= parameters.max_damping) {
      dls_step(data, chains, wall, damping, w);
      trial_cost = dls_trial_cost(model, data, target, tolerances, parameters.aim_fraction, wall, g, cost, w);
      if (trial_cost < cost) {
        improved = true;
        damping = std::max(damping / 3.0, parameters.min_damping);
        break;
      }
      damping *= 4.0;
    }
    if (!improved) {
      place(g, w.clearance);
      break;
    }
    stalled = (cost - trial_cost) < parameters.stall_relative_decrease * cost ? stalled + 1 : 0;
    g = w.trial;
    cost = trial_cost;
    w.error = w.trial_error;
    if (wall) w.clearance = w.trial_clearance;
    recorder.sample(iteration, g);
    reached = target_reached(data.points, target, tolerances) && (!wall || w.clearance.clear());
  }
  recorder.finish(iteration, g);
  IkResult result;
  result.reached = reached;
  result.iterations = iteration;
  result.simulated_time_s = iteration * time_step_s;
  result.residual_m = grasp_residual(data.points, target);
  result.posture = reached ? g : g_init;
  forward_kinematics(model, data, result.posture);
  return result;
}

}  // namespace crux
