#include "ik/gradient_descent_ik.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "body/kinematics.hpp"
#include "ik/wall_clearance.hpp"

namespace crux {

int GradientDescentParameters::max_iterations(double time_step_s) const {
  return static_cast<int>(std::floor(timeout_s / time_step_s + 1e-9));
}

namespace {

// Gradient of f at the current posture: sum of J_i^T (e_i - e_i_des), column by column
// over each operational point's chain only.
void cost_gradient(const BodyModel& model, const BodyData& data, const ReachTarget& target, Posture& gradient) {
  gradient.setZero();
  for (int k = 0; k < kOperationalPointCount; ++k) {
    const Eigen::Vector3d error = data.points[k] - (k == 0 ? target.root : target.hold_centres[k - 1]);
    for (const int i : model.chains[k]) gradient[i] += data.jacobians[k].col(i).dot(error);
  }
}

}  // namespace

IkResult solve_ik_gradient_descent(const BodyModel& model, BodyData& data, const Posture& g_init,
                                   const ReachTarget& target, const ReachTolerances& tolerances, double time_step_s,
                                   const GradientDescentParameters& parameters, const PathRecorder& recorder) {
  const int max_iterations = parameters.max_iterations(time_step_s);
  Posture g = g_init;
  Posture gradient;
  // With the wall, every joint is placed (the head and neck are no operational point's).
  const bool wall = parameters.keep_out_of_wall;
  WallClearance clearance;
  const auto place = [&](const Posture& posture) {
    if (!wall) return operational_forward_kinematics(model, data, posture);
    forward_kinematics(model, data, posture);
    wall_clearance(model, data, clearance);
  };
  const auto cost_now = [&] { return reach_cost(data.points, target) + (wall ? clearance.cost() : 0.0); };
  const auto accepted = [&] { return target_reached(data.points, target, tolerances) && (!wall || clearance.clear()); };
  place(g);
  recorder.start(g);
  int iteration = 0;
  bool reached = accepted();
  // f of the last stall_iterations + 1 iterates, for the stall exit.
  constexpr int kMaxStallWindow = 64;
  std::array<double, kMaxStallWindow + 1> recent_costs;
  const int window = std::clamp(parameters.stall_iterations, 0, kMaxStallWindow);  // the config caps it at 64
  recent_costs[0] = cost_now();
  while (!reached && iteration < max_iterations) {
    ++iteration;
    operational_jacobians(model, data);
    cost_gradient(model, data, target, gradient);
    for (int r = 0; wall && r < clearance.rows; ++r) gradient += clearance.excess[r] * clearance.gradient[r];
    for (int i = 0; i < kConfigurationDof; ++i) {
      const double next = g[i] - parameters.step_size * gradient[i];
      // "Modify descent direction": a joint whose step would cross its limit stays put.
      if (next >= model.lower_limits[i] && next <= model.upper_limits[i]) g[i] = next;
    }
    place(g);
    recorder.sample(iteration, g);
    reached = accepted();
    if (window == 0 || reached) continue;
    const double cost = cost_now();
    recent_costs[iteration % (window + 1)] = cost;
    if (iteration >= window &&
        recent_costs[(iteration - window) % (window + 1)] - cost < parameters.stall_decrease * cost &&
        tolerance_excess(data.points, target, tolerances) > parameters.stall_margin_m) {
      break;
    }
  }
  recorder.finish(iteration, g);
  IkResult result;
  result.reached = reached;
  result.iterations = iteration;
  result.simulated_time_s = iteration * time_step_s;
  result.residual_m = grasp_residual(data.points, target);
  result.posture = reached ? g : g_init;
  forward_kinematics(model, data, result.posture);  // data describes the returned posture, every joint
  return result;
}

}  // namespace crux
