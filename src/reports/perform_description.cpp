#include "reports/perform_description.hpp"

#include <fmt/format.h>

#include "common/counted.hpp"
#include "common/printable.hpp"
#include "reports/plan_description.hpp"

namespace crux {

namespace {

nlohmann::ordered_json outcome_json(const MoveOutcome& outcome) {
  nlohmann::ordered_json out;
  out["performed"] = outcome.performed();
  out["cause"] = outcome.performed() ? nlohmann::ordered_json() : nlohmann::ordered_json(enum_name(outcome.failure));
  out["simulated_s"] = outcome.seconds;
  out["max_torque_ratio"] = outcome.max_torque_ratio;
  out["peak_range_torque_nm"] = outcome.peak_range_torque;
  out["grasp_error_m"] = outcome.grasp_error_m;
  out["joint_error_rad"] = outcome.joint_error_rad;
  out["max_root_turn_rad"] = outcome.max_root_turn_rad;
  out["peak_wall_push_n"] = outcome.peak_wall_push_n;
  return out;
}

std::string cause_text(const PerformedClimb& climb) {
  const std::optional<int> failed = climb.first_failed_move();
  if (!failed) return "every move performed";
  if (!climb.start.performed()) return fmt::format("the start did not hold still ({})", enum_name(climb.cause()));
  return fmt::format("move {} failed: {}", *failed + 1, enum_name(climb.cause()));
}

}  // namespace

nlohmann::ordered_json performed_plan_json(const Wall& wall, const PerformedPlan& performed) {
  nlohmann::ordered_json out = plan_json(wall, performed.plan);
  out["replans"] = performed.replans;
  out["replan_cap_reached"] = performed.replan_cap_reached;
  out["moves_simulated"] = performed.moves_simulated;
  nlohmann::ordered_json failed = nlohmann::ordered_json::array();
  for (const FailedMove& move : performed.failed_moves) {
    failed.push_back({{"plan", move.plan},
                      {"move", move.move},
                      {"limb", enum_name(move.limb)},
                      {"hold", move.hold_id},
                      {"cause", enum_name(move.cause)}});
  }
  out["failed_moves"] = failed;
  const PerformedClimb empty;
  const PerformedClimb& climb = performed.climb ? *performed.climb : empty;
  out["reached_top"] = performed.performed();
  out["moves_performed"] = climb.moves_performed();
  const std::optional<int> first_failed = performed.climb ? climb.first_failed_move() : std::nullopt;
  out["first_failed_move"] = first_failed ? nlohmann::ordered_json(*first_failed) : nlohmann::ordered_json();
  out["cause"] = first_failed ? nlohmann::ordered_json(enum_name(climb.cause())) : nlohmann::ordered_json();
  out["max_torque_ratio"] = climb.max_torque_ratio();
  out["simulated_s"] = climb.simulated_s();
  out["start"] = performed.climb ? outcome_json(climb.start) : nlohmann::ordered_json();
  nlohmann::ordered_json moves = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < climb.moves.size(); ++k) {
    nlohmann::ordered_json move{{"limb", enum_name(performed.plan.limbs[k])}, {"hold", performed.plan.hold_ids[k]}};
    move.update(outcome_json(climb.moves[k]));
    moves.push_back(move);
  }
  out["moves"] = moves;
  return out;
}

std::string failure_words(MoveFailure failure) {
  switch (failure) {
    case MoveFailure::None:
      return "";
    case MoveFailure::GripExceeded:
      return "a hand's grip was exceeded";
    case MoveFailure::HandSlipped:
      return "a hand slipped off its hold";
    case MoveFailure::FootSlipped:
      return "a foot slipped off its hold";
    case MoveFailure::TorqueSaturated:
      return "a torque saturated, so the limb could not follow";
    case MoveFailure::HitWall:
      return "the body hit the wall";
    case MoveFailure::TimedOut:
      return "the hold was not reached in time";
    case MoveFailure::Unstable:
      return "the simulation became unstable";
  }
  return "";
}

std::string performed_plan_text(const Wall& wall, const PerformedPlan& performed) {
  const Plan& plan = performed.plan;
  // A search that found nothing once moves were refused says so, not that no climb exists.
  const bool none_left = !plan.found && !plan.stopped_at_limit && !performed.failed_moves.empty();
  std::string out = none_left ? fmt::format(
                                    "no climb is left on '{}' under the {} model once the moves that failed in "
                                    "MuJoCo are refused ({} explored, {})\n",
                                    printable(wall.name), enum_name(plan.physics_model),
                                    counted(plan.expanded_states, "state"), counted(plan.ik_solves, "IK solve"))
                              : plan_text(wall, plan);
  if (performed.climb) {
    const PerformedClimb& climb = *performed.climb;
    out += fmt::format("performed in MuJoCo: {} of {} performed, {}; {:.1f} s simulated, largest torque ratio {:.2f}\n",
                       climb.moves_performed(), counted(climb.planned_moves, "move"), cause_text(climb),
                       climb.simulated_s(), climb.max_torque_ratio());
  }
  if (!performed.failed_moves.empty()) {
    out += fmt::format("{} after moves failed in MuJoCo ({} simulated):\n", counted(performed.replans, "replan"),
                       counted(performed.moves_simulated, "move"));
    for (const FailedMove& move : performed.failed_moves) {
      out += fmt::format("  plan {}, move {}: {} -> hold {} failed ({})\n", move.plan + 1, move.move + 1,
                         enum_name(move.limb), move.hold_id, enum_name(move.cause));
    }
    if (performed.replan_cap_reached) out += "  the cap on replans was reached (--plan-max-replans raises it)\n";
  }
  return out;
}

}  // namespace crux
