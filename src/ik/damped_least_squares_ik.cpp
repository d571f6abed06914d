#include "ik/damped_least_squares_ik.hpp"

#include <Eigen/Cholesky>

#include "body/kinematics.hpp"

namespace crux {

namespace {

constexpr int kTaskSize = 3 * kOperationalPointCount;
using TaskJacobian = Eigen::Matrix<double, kTaskSize, kConfigurationDof>;
using TaskVector = Eigen::Matrix<double, kTaskSize, 1>;
using TaskMatrix = Eigen::Matrix<double, kTaskSize, kTaskSize>;

void stack_task(const BodyData& data, const ReachTarget& target, TaskJacobian& jacobian, TaskVector& error) {
  for (int k = 0; k < kOperationalPointCount; ++k) {
    jacobian.middleRows<3>(3 * k) = data.jacobians[k];
    error.segment<3>(3 * k) = data.points[k] - (k == 0 ? target.root : target.hold_centres[k - 1]);
  }
}

}  // namespace

IkResult solve_ik_damped_least_squares(const BodyModel& model, BodyData& data, const Posture& g_init,
                                       const ReachTarget& target, const ReachTolerances& tolerances,
                                       const DampedLeastSquaresSettings& settings, const PathRecorder& recorder) {
  TaskJacobian jacobian;
  TaskVector error;
  TaskMatrix normal;
  Eigen::LLT<TaskMatrix> factor;
  Posture g = g_init, trial, gradient;

  forward_kinematics(model, data, g);
  recorder.start(g);
  double cost = reach_cost(data.points, target);
  double damping = settings.initial_damping;
  int iteration = 0, stalled = 0;
  bool reached = target_reached(data.points, target, tolerances);
  while (!reached && iteration < settings.max_iterations && stalled < settings.stall_iterations) {
    ++iteration;
    operational_jacobians(model, data);
    stack_task(data, target, jacobian, error);
    gradient.noalias() = jacobian.transpose() * error;
    // Active set: a joint at a limit whose descent direction points out of range is
    // frozen for this step, so the remaining joints absorb the motion.
    for (int i = kRootDof; i < kConfigurationDof; ++i) {
      if ((g[i] <= model.lower_limits[i] && gradient[i] > 0.0) ||
          (g[i] >= model.upper_limits[i] && gradient[i] < 0.0)) {
        jacobian.col(i).setZero();
      }
    }
    normal.noalias() = jacobian * jacobian.transpose();
    bool improved = false;
    double trial_cost = cost;
    while (damping <= settings.max_damping) {
      TaskMatrix damped = normal;
      damped.diagonal().array() += damping;
      factor.compute(damped);
      trial.noalias() = g - jacobian.transpose() * factor.solve(error);
      trial = trial.cwiseMax(model.lower_limits).cwiseMin(model.upper_limits);
      forward_kinematics(model, data, trial);
      trial_cost = reach_cost(data.points, target);
      if (trial_cost < cost) {
        improved = true;
        damping = std::max(damping / 3.0, settings.min_damping);
        break;
      }
      damping *= 4.0;
    }
    if (!improved) {
      forward_kinematics(model, data, g);
      break;
    }
    stalled = (cost - trial_cost) < settings.stall_relative_decrease * cost ? stalled + 1 : 0;
    g = trial;
    cost = trial_cost;
    recorder.sample(iteration, g);
    reached = target_reached(data.points, target, tolerances);
  }
  recorder.finish(iteration, g);
  IkResult result;
  result.reached = reached;
  result.iterations = iteration;
  result.simulated_time_s = iteration * settings.time_step_s;
  result.residual_m = grasp_residual(data.points, target);
  result.posture = reached ? g : g_init;
  if (!reached) forward_kinematics(model, data, g_init);
  return result;
}

}  // namespace crux
