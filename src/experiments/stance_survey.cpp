#include "experiments/stance_survey.hpp"

#include <limits>
#include <set>

#include "common/input_error.hpp"
#include "common/random.hpp"
#include "common/random_stream.hpp"
#include "configurations/reachability.hpp"
#include "ik/ik_path.hpp"
#include "wall/random_wall.hpp"

namespace crux {

namespace {

struct SurveyedStance {
  Posture posture;
  HoldConfiguration complete;
  Limb next;
};

// A reached move: the posture it starts from and the three holds kept while it is made.
struct SurveyedMove {
  Posture from, to;
  HoldConfiguration kept, complete;
};

// The distinct stances a random walk of kinematic moves reaches, body out of the wall.
std::vector<SurveyedStance> walk(const BodyModel& model, const Wall& wall, const StanceSurveyParameters& parameters,
                                 const RandomStream& moves, std::uint64_t wall_index, bool& start_reached,
                                 std::vector<SurveyedMove>& reached_moves) {
  ClimbingParameters kinematic = parameters.climbing;
  kinematic.physics.model = PhysicsModel::Kinematic;
  kinematic.reachability.ik.wall = WallRule::Avoid;
  std::vector<SurveyedStance> stances;
  try {
    ClimbingMdp mdp(model, wall, kinematic);
    start_reached = true;
    std::set<std::uint64_t> seen;
    for (int move = 0; move < parameters.moves; ++move) {
      const auto candidates = mdp.candidates();
      const ActionCode hold = candidates[moves.below(candidates.size(), wall_index, move)].wall;
      const Limb free = mdp.configuration().free_limb();
      const HoldConfiguration kept = mdp.configuration();
      const HoldConfiguration complete = kept.with(free, hold);
      const Posture from = mdp.posture();
      const StepOutcome outcome = mdp.step(hold);
      if (!outcome.reached) continue;
      reached_moves.push_back({from, *outcome.posture, kept, complete});
      const Limb next = next_free_limb(free);
      const std::uint64_t key = encode(complete, wall.hold_count()) * kLimbCount + static_cast<std::uint64_t>(next);
      if (seen.insert(key).second) stances.push_back({*outcome.posture, complete, next});
    }
  } catch (const InputError&) {
    start_reached = false;  // the start is out of reach: nothing to survey
  }
  return stances;
}

std::string failure(StanceCheck& check, StanceCheck& gripless, const BodyModel& model, const Posture& posture,
                    const HoldConfiguration& configuration) {
  const StaticEquilibriumResult& result = check.solve(posture, configuration);
  if (result.feasible) return {};
  if (result.balanced) return stance_failure_name(StanceVerdict::Joint, model.joints[result.binding_joint].name);
  return stance_failure_name(
      gripless.solve(posture, configuration).balanced ? StanceVerdict::Grip : StanceVerdict::Contacts, {});
}

// The replay's samples of each move, before its last (the new stance, checked on its
// own), on the three holds kept during the move; only moves whose start holds on them.
void check_paths(const BodyModel& model, const Wall& wall, const StanceSurveyParameters& parameters,
                 const std::vector<SurveyedMove>& moves, StanceCheck& check, StanceTally& tally) {
  BodyData data(model);
  std::vector<Posture> path, samples;
  for (const SurveyedMove& move : moves) {
    if (!check.solve(move.from, move.kept).feasible) continue;
    const ReachTarget target = reach_target(model, wall, move.complete, parameters.climbing.reachability.root);
    ik_path_samples(model, data, move.from, move.to, target, parameters.climbing.reachability.ik,
                    parameters.path_samples, path, samples);
    int failing = 0;
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) failing += !check.solve(samples[i], move.kept).feasible;
    ++tally.path_moves;
    tally.path_moves_failing += failing > 0;
    tally.path_samples += static_cast<int>(samples.size()) - 1;
    tally.path_samples_failing += failing;
  }
}

void add(StanceTally& into, const StanceTally& from) {
  into.path_moves += from.path_moves;
  into.path_moves_failing += from.path_moves_failing;
  into.path_samples += from.path_samples;
  into.path_samples_failing += from.path_samples_failing;
  into.stances += from.stances;
  into.four_held += from.four_held;
  into.three_held += from.three_held;
  for (const auto& [name, count] : from.four_failures) into.four_failures[name] += count;
  for (const auto& [name, count] : from.three_failures) into.three_failures[name] += count;
}

}  // namespace

std::string stance_failure_name(StanceVerdict verdict, const std::string& joint) {
  switch (verdict) {
    case StanceVerdict::Grip:
      return "grip";
    case StanceVerdict::Contacts:
      return "contacts";
    case StanceVerdict::Joint:
      return joint;
    case StanceVerdict::Holds:
      break;
  }
  return {};
}

StanceSurvey survey_stances(const BodyModel& model, const StanceSurveyParameters& parameters,
                            const std::function<void(int)>& progress) {
  StanceSurvey survey;
  const RandomStream moves(parameters.wall_seed, "stance survey moves");
  PhysicsParameters gripless_physics = parameters.climbing.physics;
  gripless_physics.grip = std::numeric_limits<double>::infinity();
  for (int i = 0; i < parameters.wall_count; ++i) {
    WallStances& surveyed = survey.walls.emplace_back();
    surveyed.seed = derive_seed(parameters.wall_seed, static_cast<std::uint64_t>(i));
    const Wall wall = generate_random_wall(surveyed.seed, parameters.walls);
    std::vector<SurveyedMove> reached_moves;
    const std::vector<SurveyedStance> stances =
        walk(model, wall, parameters, moves, static_cast<std::uint64_t>(i), surveyed.start_reached, reached_moves);
    StanceCheck check(model, wall, parameters.climbing.physics);
    StanceCheck gripless(model, wall, gripless_physics);
    StanceTally& tally = surveyed.tally;
    for (const SurveyedStance& stance : stances) {
      ++tally.stances;
      const std::string on_four = failure(check, gripless, model, stance.posture, stance.complete);
      if (!on_four.empty()) {
        ++tally.four_failures[on_four];
        continue;
      }
      ++tally.four_held;
      const std::string on_three =
          failure(check, gripless, model, stance.posture, stance.complete.with(stance.next, kFree));
      if (!on_three.empty()) {
        ++tally.three_failures[on_three];
        continue;
      }
      ++tally.three_held;
    }
    check_paths(model, wall, parameters, reached_moves, check, tally);
    add(survey.total, tally);
    if (progress) progress(i + 1);
  }
  return survey;
}

}  // namespace crux
