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

}  // namespace

IkResult solve_ik_damped_least_squares(const BodyModel& model, BodyData& data, const Posture& g_init,
                                       const ReachTarget& target, const ReachTolerances& tolerances, double time_step_s,
                                       const DampedLeastSquaresParameters& settings, const PathRecorder& recorder) {
  TaskVector error;
  TaskMatrix normal;
  Posture g = g_init, trial, gradient, step;
  const ChainCoordinates chains = chain_coordinates(model);
  // With the wall, every joint is placed (the head and neck are no operational point's),
  // and the step solves the stacked task of ik/wall_clearance.hpp.
  const bool wall = settings.keep_out_of_wall;
  WallClearance clearance, trial_clearance;
  StackedTaskVector wall_error;
  StackedTaskMatrix wall_normal;
  const auto place = [&](const Posture& posture, WallClearance& out) {
    if (!wall) return operational_forward_kinematics(model, data, posture);
    forward_kinematics(model, data, posture);
    wall_clearance(model, data, out);
  };

  place(g, clearance);
  recorder.start(g);
  task_error(data, target, tolerances, settings.aim_fraction, error);
  double cost = 0.5 * error.squaredNorm() + (wall ? clearance.cost() : 0.0);
  double damping = settings.initial_damping;
  int iteration = 0, stalled = 0;
  bool reached = target_reached(data.points, target, tolerances) && (!wall || clearance.clear());
  while (!reached && iteration < settings.max_iterations && stalled < settings.stall_iterations) {
    ++iteration;
    operational_jacobians(model, data);
    task_transpose_product(data, chains, 0, error, gradient);
    for (int r = 0; wall && r < clearance.rows; ++r) gradient += clearance.excess[r] * clearance.gradient[r];
    // Active set: a joint at a limit whose descent direction points out of range is
    // frozen for this step, so the remaining joints absorb the motion.
    CoordinateSet frozen = 0;
    for (int i = kRootDof; i < kConfigurationDof; ++i) {
      if ((g[i] <= model.lower_limits[i] && gradient[i] > 0.0) ||
          (g[i] >= model.upper_limits[i] && gradient[i] < 0.0)) {
        frozen |= CoordinateSet{1} << i;
      }
    }
    // g's stacked task: its rows stay g's while the trials move data's points only.
    std::optional<StackedTask> wall_task;
    if (wall) {
      stack_wall_error(clearance, error, wall_error);
      wall_task.emplace(data, chains, clearance.gradients(), frozen);
      wall_task->normal_matrix(wall_normal);
    } else {
      task_normal_matrix(data, chains, frozen, normal);
    }
    bool improved = false;
    double trial_cost = cost;
    TaskVector trial_error;
    while (damping <= settings.max_damping) {
      if (wall) {
        StackedTaskMatrix damped = wall_normal;
        damped.diagonal().array() += damping;
        const Eigen::LLT<Eigen::Ref<StackedTaskMatrix>> factor(damped);  // in place, as below
        wall_task->transpose_product(factor.solve(wall_error), step);
      } else {
        TaskMatrix damped = normal;
        damped.diagonal().array() += damping;
        // Factorised in place: the same numbers, one copy of the matrix fewer.
        const Eigen::LLT<Eigen::Ref<TaskMatrix>> factor(damped);
        // data.jacobians are still g's: forward kinematics of a trial moves points only.
        task_transpose_product(data, chains, frozen, factor.solve(error), step);
      }
      trial = g - step;
      trial = trial.cwiseMax(model.lower_limits).cwiseMin(model.upper_limits);
      operational_forward_kinematics(model, data, trial);
      task_error(data, target, tolerances, settings.aim_fraction, trial_error);
      trial_cost = 0.5 * trial_error.squaredNorm();
      // The wall's term is never negative: a trial whose points alone cost no less than g
      // is refused without placing the rest of the body.
      if (wall && trial_cost < cost) {
        remaining_forward_kinematics(model, data, trial);
        wall_clearance(model, data, trial_clearance);
        trial_cost += trial_clearance.cost();
      }
      if (trial_cost < cost) {
        improved = true;
        damping = std::max(damping / 3.0, settings.min_damping);
        break;
      }
      damping *= 4.0;
    }
    if (!improved) {
      place(g, clearance);
      break;
    }
    stalled = (cost - trial_cost) < settings.stall_relative_decrease * cost ? stalled + 1 : 0;
    g = trial;
    cost = trial_cost;
    error = trial_error;
    if (wall) clearance = trial_clearance;
    recorder.sample(iteration, g);
    reached = target_reached(data.points, target, tolerances) && (!wall || clearance.clear());
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
