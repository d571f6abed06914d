#pragma once
// Run-time choice between the paper's gradient descent and crux's fast solver; both
// share inputs, outputs and the termination test.

#include "common/enum_names.hpp"
#include "ik/damped_least_squares_ik.hpp"
#include "ik/gradient_descent_ik.hpp"

namespace crux {

enum class IkSolverKind { Paper, Fast };
template <>
struct EnumNames<IkSolverKind> {
  static constexpr std::array<EnumName<IkSolverKind>, 2> entries{
      {{IkSolverKind::Fast, "fast"}, {IkSolverKind::Paper, "paper"}}};
};

// What the IK does about the wall (docs/MODEL.md, choice C24): ignore it, as the paper's
// model does (the default); reject a solved posture that passes through it
// (body/wall_penetration); or keep the body out of it while solving (ik/wall_clearance).
enum class WallRule { Ignore, Reject, Avoid };
template <>
struct EnumNames<WallRule> {
  static constexpr std::array<EnumName<WallRule>, 3> entries{
      {{WallRule::Ignore, "ignore"}, {WallRule::Reject, "reject"}, {WallRule::Avoid, "avoid"}}};
};

struct IkParameters {
  IkSolverKind solver = IkSolverKind::Fast;
  // What both solvers share: the termination test and the simulated time per iteration
  // (docs/MODEL.md, choice C9; the paper's time-out is counted in it).
  ReachTolerances tolerances;
  double time_step_s = 0.002;
  // Give up before the first iteration when a hold is beyond its limb's reach envelope
  // (beyond_reach): the verdict cannot change, only the time spent reaching it.
  bool rule_out_beyond_reach = true;
  WallRule wall = WallRule::Ignore;
  GradientDescentParameters paper;
  DampedLeastSquaresParameters fast;
};

// Dispatches to the chosen solver, after the reach envelope's check.
IkResult solve_ik(const BodyModel& model, BodyData& data, const Posture& g_init, const ReachTarget& target,
                  const IkParameters& parameters, const PathRecorder& recorder = {});

}  // namespace crux
