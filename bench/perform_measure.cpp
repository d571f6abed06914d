// Climbs performed in MuJoCo on random walls 1 to N (docs/PHYSICS.md, "Performed in
// MuJoCo"): the static model's exact plan of each wall, performed move after move from the
// simulated state the last one left, and each move performed alone from its planned
// stance, so that one failure does not hide the moves after it.
//   crux-perform-measure [last wall, 30] [incline, 0] [servo saturation angle, rad]
// With `agreement` as the first argument, the static model's verdict against MuJoCo
// instead: each stance of each wall's kinematic plan (solved with ik.wall = avoid, so that
// no stance starts in the wall), on its four holds and on the three left when the next limb
// lets go, held for 2 s in MuJoCo with its feed-forward; a confusion table of the two.
//   crux-perform-measure agreement [last wall, 30] [incline, 0]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "body/urdf_loader.hpp"
#include "climbing/stance_check.hpp"
#include "common/input_error.hpp"
#include "experiments/shortest_plan.hpp"
#include "simulation/mjcf_model.hpp"
#include "simulation/move_reference.hpp"
#include "wall/random_wall.hpp"

using namespace crux;

namespace {

struct Tally {
  int moves = 0, performed = 0;
  std::map<std::string, int> unsettled;  // planned stances that did not hold still, by cause
  std::map<std::string, int> causes;
  std::map<std::string, std::vector<double>> turns;  // each move's largest root turn, rad, by cause
  double simulated_s = 0.0, max_torque_ratio = 0.0;
  std::vector<double> grasp_errors, joint_errors;  // of the performed moves, at their end
  void add(const MoveOutcome& outcome) {
    ++moves;
    performed += outcome.performed() ? 1 : 0;
    ++causes[std::string(enum_name(outcome.failure))];
    turns[std::string(enum_name(outcome.failure))].push_back(outcome.max_root_turn_rad);
    simulated_s += outcome.seconds;
    if (outcome.performed()) {
      max_torque_ratio = std::max(max_torque_ratio, outcome.max_torque_ratio);
      grasp_errors.push_back(outcome.grasp_error_m);
      joint_errors.push_back(outcome.joint_error_rad);
    }
  }
  static double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
  }
  static double largest(const std::vector<double>& values) {
    return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
  }
  void print(const char* title) const {
    std::printf("%s: %d of %d moves performed (%.1f %%); largest torque ratio of a performed move %.2f\n", title,
                performed, moves, 100.0 * performed / std::max(moves, 1), max_torque_ratio);
    std::printf(
        "  tracking at a performed move's end: grasp point to hold median %.3f m (largest %.3f), largest joint "
        "error median %.3f rad (largest %.3f)\n",
        median(grasp_errors), largest(grasp_errors), median(joint_errors), largest(joint_errors));
    for (const auto& [cause, count] : causes) {
      std::printf("  %-18s %d (median root turn %.3f rad)\n", cause.c_str(), count, median(turns.at(cause)));
    }
    for (const auto& [cause, count] : unsettled) {
      std::printf("  a planned stance did not hold still (%s): %d\n", cause.c_str(), count);
    }
  }
};

// Static verdict (holds, refused) x MuJoCo (held still for 2 s, not), and the causes of
// the disagreements.
int measure_agreement(int last_wall, double incline) {
  const BodyModel model = load_body_model(default_body_model_path());
  const StrengthProfile limits =
      motor_limits(model, published_strength_profile(model, model.total_mass, model.stature));
  ClimbingParameters kinematic;
  kinematic.reachability.ik.wall = WallRule::Avoid;
  PhysicsParameters physics;
  physics.model = PhysicsModel::Static;
  MoveParameters move;
  move.grasp_radius = kinematic.reachability.ik.tolerances.grasp_radius;
  std::map<std::pair<bool, bool>, int> table;
  std::map<std::string, int> held_causes;
  int walls = 0;
  for (int seed = 1; seed <= last_wall; ++seed) {
    Wall wall = generate_random_wall(seed);
    wall.incline_deg = incline;
    Plan plan;
    try {
      plan = shortest_plan(model, wall, kinematic);
    } catch (const InputError&) {
      continue;
    }
    if (!plan.found) continue;
    ++walls;
    StanceCheck check(model, wall, physics);
    MoveReferences references(model, wall, physics, kinematic.reachability, 16);
    SimulatedClimber climber(model, wall, physics, limits, plan.postures[0], ServoParameters{});
    HoldConfiguration held = start_configuration(wall);
    for (int k = 0; k <= plan.length; ++k) {
      if (k > 0) held = held.with(plan.limbs[k - 1], wall.index_of(plan.hold_ids[k - 1]));
      const Limb next = k < plan.length ? plan.limbs[k] : k > 0 ? next_free_limb(plan.limbs[k - 1]) : Limb::RightHand;
      for (const HoldConfiguration& holds : {held, held.with(next, kFree)}) {
        const Posture& posture = plan.postures[k];
        const bool holds_statically = check.solve(posture, holds).feasible;
        climber.place(posture, holds);
        const MoveOutcome outcome =
            hold_still(climber, posture, holds, references.holding(posture, holds).torques, 2.0, move);
        ++table[{holds_statically, outcome.performed()}];
        if (holds_statically != outcome.performed()) {
          ++held_causes[(holds_statically ? "static holds, MuJoCo: " : "static refuses, MuJoCo holds still: ") +
                        std::string(enum_name(outcome.failure))];
        }
      }
    }
    std::printf("wall %d: %d stances\n", seed, plan.length + 1);
  }
  std::printf(
      "\n%d walls with a kinematic plan (ik.wall = avoid) at %.0f degrees; each stance on 4 and on 3 holds, "
      "held for 2 s\n",
      walls, incline);
  std::printf("                 MuJoCo holds still   does not\n");
  std::printf("static holds     %18d   %8d\n", table[{true, true}], table[{true, false}]);
  std::printf("static refuses   %18d   %8d\n", table[{false, true}], table[{false, false}]);
  for (const auto& [cause, count] : held_causes) std::printf("  %s: %d\n", cause.c_str(), count);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "agreement") {
    return measure_agreement(argc > 2 ? std::atoi(argv[2]) : 30, argc > 3 ? std::atof(argv[3]) : 0.0);
  }
  const int last_wall = argc > 1 ? std::atoi(argv[1]) : 30;
  const double incline = argc > 2 ? std::atof(argv[2]) : 0.0;
  ServoParameters servo;
  if (argc > 3) servo.saturation_angle = std::atof(argv[3]);
  const BodyModel model = load_body_model(default_body_model_path());
  const StrengthProfile limits =
      motor_limits(model, published_strength_profile(model, model.total_mass, model.stature));
  ClimbingParameters parameters;
  parameters.physics.model = PhysicsModel::Static;
  parameters.reachability.ik.wall = WallRule::Avoid;
  MoveParameters move;
  move.grasp_radius = parameters.reachability.ik.tolerances.grasp_radius;
  Tally in_sequence, alone;
  int planned = 0, climbed = 0;
  double simulated_s = 0.0, wall_clock_s = 0.0;
  for (int seed = 1; seed <= last_wall; ++seed) {
    Wall wall = generate_random_wall(seed);
    wall.incline_deg = incline;
    Plan plan;
    try {
      plan = shortest_plan(model, wall, parameters);
    } catch (const InputError& error) {
      std::printf("wall %d: %s\n", seed, error.what());
      continue;
    }
    if (!plan.found) {
      std::printf("wall %d: no static plan\n", seed);
      continue;
    }
    ++planned;
    SimulatedClimber climber(model, wall, parameters.physics, limits, plan.postures[0], servo);
    MoveReferences references(model, wall, parameters.physics, parameters.reachability, 16);
    const auto started = std::chrono::steady_clock::now();
    const auto perform_from = [&](int first, bool sequence, Tally& tally) {
      HoldConfiguration held = start_configuration(wall);
      for (int k = 0; k < first; ++k) held.holds[static_cast<int>(plan.limbs[k])] = wall.index_of(plan.hold_ids[k]);
      climber.place(plan.postures[first], held);
      MoveOutcome outcome = hold_still(climber, plan.postures[first], held,
                                       references.holding(plan.postures[first], held).torques, 2.0, move);
      simulated_s += outcome.seconds;
      if (!outcome.performed()) ++tally.unsettled[std::string(enum_name(outcome.failure))];
      int performed = 0;
      for (int k = first; k < plan.length && outcome.performed() && (sequence || k == first); ++k) {
        const Limb limb = plan.limbs[k];
        const int hold = wall.index_of(plan.hold_ids[k]);
        const MoveReference reference =
            references.move(plan.postures[k], plan.postures[k + 1], held.with(limb, kFree), held.hold(limb), hold);
        outcome = perform_move(climber, reference, move);
        simulated_s += outcome.seconds;
        tally.add(outcome);
        performed += outcome.performed() ? 1 : 0;
        held = held.with(limb, hold);
      }
      return performed;
    };
    const int performed = perform_from(0, true, in_sequence);
    climbed += performed == plan.length ? 1 : 0;
    for (int k = 0; k < plan.length; ++k) perform_from(k, false, alone);
    wall_clock_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::printf("wall %d: plan of %d moves, %d performed in sequence\n", seed, plan.length, performed);
  }
  std::printf("\n%d walls with a static plan at %.0f degrees; %d climbed to the top in MuJoCo\n", planned, incline,
              climbed);
  in_sequence.print("In sequence, from the start");
  alone.print("Each move alone, from its planned stance");
  std::printf("Simulated %.1f s in %.1f s of wall-clock time: %.1f times real time\n", simulated_s, wall_clock_s,
              simulated_s / wall_clock_s);
}
