#include "experiments/learning_run.hpp"

namespace crux {

namespace {

// One climb from the start following the best Q_wall action, recorded in `result`. The
// cache may grow, but no table is updated.
void greedy_climb(ClimbingMdp& mdp, const QTable& q_wall, int cap, RunResult& result) {
  mdp.reset();
  std::vector<Posture> postures{mdp.posture()};
  std::vector<ClimbMove> moves;
  for (int step = 1; step <= cap; ++step) {
    const auto candidates = mdp.candidates();
    if (candidates.empty()) return;
    std::size_t best = 0;
    for (std::size_t i = 1; i < candidates.size(); ++i) {
      if (q_wall.value(mdp.state().wall, candidates[i].wall) > q_wall.value(mdp.state().wall, candidates[best].wall)) best = i;
    }
    const ActionCode hold = candidates[best].wall;  // step() refills the candidates
    const StepOutcome outcome = mdp.step(hold);
    if (!outcome.reached) return;
    moves.push_back({mdp.wall().holds[hold].id, outcome.reward});
    postures.push_back(*outcome.posture);
    if (outcome.finished) {
      result.greedy_length = step;
      result.greedy_climb = std::move(postures);
      result.greedy_moves = std::move(moves);
      return;
    }
  }
}

}  // namespace

RunResult run_learning(const BodyModel& model, const Wall& wall, const LearningParameters& parameters,
                       std::uint64_t seed, const QTable* initial_q_grid,
                       const std::function<void(int)>& progress) {
  ClimbingMdp mdp(model, wall, parameters.climbing);
  DynaQAgent agent(mdp.wall_action_count(), mdp.grid_action_count(), parameters.dyna, seed);
  if (initial_q_grid != nullptr) agent.set_q_grid(*initial_q_grid);
  RunResult result;
  result.iterations.reserve(parameters.iterations);
  std::vector<Posture> climb{mdp.posture()};
  int episode = 0, episode_start = 0;
  agent.observe(mdp.state(), mdp.candidates());
  for (int iteration = 0; iteration < parameters.iterations; ++iteration) {
    const StateCouple state = mdp.state();
    const std::span<const ActionCandidate> candidates = mdp.candidates();
    const ActionChoice choice = agent.choose(state, candidates);
    const ActionCandidate action = candidates[choice.candidate];
    IterationRecord record{episode, choice.regime, wall.holds[action.wall].id};
    record.grid_state = static_cast<std::uint32_t>(state.grid);
    record.tile = action.grid;
    record.back_to_left_hold = action.wall == mdp.left_hold();
    if (action.grid != kNoAction) {
      const Eigen::Vector3d offset = wall.holds[action.wall].position - mdp.placement().tile_centre(action.grid);
      record.tile_offset_y = static_cast<float>(offset.y());
      record.tile_offset_z = static_cast<float>(offset.z());
    }
    const StepOutcome outcome = mdp.step(action.wall);
    agent.observe(mdp.state(), mdp.candidates());
    agent.learn({state.wall, state.grid, action.wall, action.grid, outcome.reward, mdp.state().wall, mdp.state().grid});
    record.success = outcome.reached;
    record.root_rise_m = outcome.root_rise_m;
    record.reward = outcome.reward;
    result.iterations.push_back(record);
    if (outcome.reached) climb.push_back(*outcome.posture);
    if (outcome.finished) {
      result.episode_lengths.push_back(iteration + 1 - episode_start);
      episode_start = iteration + 1;
      ++episode;
      result.last_climb = std::move(climb);
      climb.assign(1, mdp.posture());
    }
    if (progress) progress(iteration + 1);
  }
  result.reached_configurations = mdp.reacher().cache().reached_count();
  result.unreachable_configurations = mdp.reacher().cache().unreachable_count();
  result.ik_solves = mdp.reacher().solves();
  greedy_climb(mdp, agent.q_wall(), parameters.greedy_cap, result);
  result.q_grid = agent.q_grid();
  result.explored_pairs = agent.model().size();
  result.planning_updates = agent.planning_updates();
  return result;
}

}  // namespace crux
