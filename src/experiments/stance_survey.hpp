#pragma once
// How many of the stances a kinematic climber reaches the static model would hold, and
// why the others fail (docs/PHYSICS.md, "Which stances hold"; crux stances). On each
// wall a random walk of kinematic moves, with the body kept out of the wall as the
// static model keeps it (ik.wall = avoid), collects the distinct reached stances (a
// 4-configuration and the limb that lets go next); each is checked on its four holds
// and on the three left.

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "climbing/climbing_mdp.hpp"
#include "wall/random_wall.hpp"

namespace crux {

// Why a stance does not hold: grip (it balances once the hands' grip is unbounded),
// contacts (no forces in the friction cones balance it even then), or a joint (it
// balances, but that joint's torque is above its limit: effort > 1).
enum class StanceVerdict { Holds, Grip, Contacts, Joint };

struct StanceTally {
  int stances = 0;
  int four_held = 0;   // held on four holds
  int three_held = 0;  // ... and on the three left
  // Failures on four holds, and on three among those held on four: by verdict, and for
  // Joint by the joint's name.
  std::map<std::string, int> four_failures, three_failures;
  // The movements between stances as the replay draws them (ik/ik_path): reached moves
  // whose start holds on the three holds kept during the move, and of those the moves
  // with a sample that does not; the samples before the last, and those that fail.
  int path_moves = 0, path_moves_failing = 0;
  int path_samples = 0, path_samples_failing = 0;
};

struct WallStances {
  std::uint64_t seed = 0;
  bool start_reached = false;  // false: the wall's start is out of reach, and it is not counted
  StanceTally tally;
};

struct StanceSurvey {
  std::vector<WallStances> walls;
  StanceTally total;
};

// A bound on stances.moves: the survey keeps every distinct stance's posture.
inline constexpr int kMaxStanceMoves = 100000;

struct StanceSurveyParameters {
  std::uint64_t wall_seed = 1;  // wall i from derive_seed(wall_seed, i), as crux filter-stats
  int wall_count = 30;
  int moves = 300;        // random moves per wall
  int path_samples = 16;  // samples per movement, as the replay draws (the last is the new stance)
  RandomWallParameters walls;
  ClimbingParameters climbing;  // its physics are the static model's parameters
};

// The name of a failure's reason in StanceTally: "grip", "contacts", or the joint's.
std::string stance_failure_name(StanceVerdict verdict, const std::string& joint);

StanceSurvey survey_stances(const BodyModel& model, const StanceSurveyParameters& parameters,
                            const std::function<void(int)>& progress = {});

}  // namespace crux
