#pragma once
// One learning run on one wall (Algorithm 2): Dyna-Q over the climbing MDP for a fixed
// number of iterations, one real action each, recording what Table I and Figs. 2b, 3
// and 4 are made of.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "climbing/climbing_mdp.hpp"
#include "climbing/policy_network.hpp"
#include "learning/dyna_q.hpp"

namespace crux {

struct LearningParameters {
  ClimbingParameters climbing;
  DynaParameters dyna;
  int iterations = 8000;
  int greedy_cap = 500;  // actions allowed to the greedy policy's evaluation climb
};

struct IterationRecord {
  int episode = 0;
  Regime regime = Regime::Random;
  int hold_id = 0;  // the hold tried
  bool success = false;
  double root_rise_m = 0.0;
  double reward = 0.0;
  // In agent space, for the diagnosis of transferred choices: the state, the tile tried
  // (kNoAction outside the grid), the hold's offset from that tile's centre (y, z, in
  // m), and whether the hold is the one the free limb just left.
  std::uint32_t grid_state = 0;
  ActionCode tile = kNoAction;
  float tile_offset_y = 0.0f, tile_offset_z = 0.0f;
  bool back_to_left_hold = false;
  bool fell = false;  // the failed move left the climber stuck: back to the start (docs/MODEL.md, C27)
};

// A reached move of a recorded climb: the hold taken and the reward.
struct ClimbMove {
  int hold_id = 0;
  double reward = 0.0;
};

struct RunResult {
  std::vector<IterationRecord> iterations;
  // Under the static model a climber can fall, and iterations.csv says where (its `fell`
  // column); the kinematic model's files keep the paper's columns.
  bool can_fall = false;
  std::vector<int> episode_lengths;  // completed episodes, in iterations (failed ones included)
  QTable q_grid{1};
  // Postures of the last completed climb: the start, then one per reached move, the
  // finishing move's included.
  std::vector<Posture> last_climb;
  std::size_t reached_configurations = 0, unreachable_configurations = 0, ik_solves = 0;
  // physics.model = dynamic: the distinct moves performed in MuJoCo, and those performed.
  bool simulates = false;
  std::size_t moves_simulated = 0, moves_performed = 0;
  std::size_t explored_pairs = 0;      // distinct problem-space (state, action) pairs taken
  std::uint64_t planning_updates = 0;  // Dyna's model updates, over the run
  // Length of one climb by the learnt greedy policy (best Q_wall action, ties to the
  // first candidate) after learning; -1 if it does not finish within greedy_cap actions.
  int greedy_length = -1;
  // That climb when it finishes (else empty): its postures (the start, then one per
  // move) and its moves. A finished greedy climb has no unreachable move: after one, the
  // state, the table and so the choice would stay the same until the cap.
  std::vector<Posture> greedy_climb;
  std::vector<ClimbMove> greedy_moves;
};

// Checkpoints of a long run (experiments/run_checkpoint.hpp): every `every` iterations
// (0: never) the run's whole state (tables, model, cache, counters, records so far) is
// handed to `save`. A run given a saved `resume` state continues from it and ends with
// the same result as a run never stopped. The random streams are addressed by the
// iteration, so the counters are all they need.
struct RunCheckpoints {
  int every = 0;
  std::function<void(std::string state, int iterations_done)> save;
  std::string resume;                                  // empty: from the start
  std::string source;                                  // names the resumed state in errors
  std::function<void(int iterations_done)> resumed{};  // told where a resumed run goes on from
};

// Deterministic in `seed`. `initial_q_grid` starts the grid table from transferred
// knowledge; Q_wall always starts empty. `policy`: under the network transfer mode, the
// network whose scores of each state's candidates order exploration.
RunResult run_learning(const BodyModel& model, const Wall& wall, const LearningParameters& parameters,
                       std::uint64_t seed, const QTable* initial_q_grid = nullptr,
                       const std::function<void(int iterations_done)>& progress = {},
                       const RunCheckpoints* checkpoints = nullptr, const PolicyNetwork* policy = nullptr);

}  // namespace crux
