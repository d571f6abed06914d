#include "experiments/learning_run.hpp"

#include "body/kinematics.hpp"
#include "common/checkpoint_stream.hpp"

namespace crux {

namespace {

// The network mode's scores of each state's candidates: the reach observation of the
// state, whose failed moves are those the agent's model has seen fail from it.
class CandidateScores {
 public:
  CandidateScores(const BodyModel& model, const PolicyNetwork& network, const Wall& wall, double max_span_m)
      : model_(model), network_(network), workspace_(model, network, wall.hold_count()), max_span_m_(max_span_m) {
    holds_.reserve(wall.hold_count());
    failed_.reserve(wall.hold_count());
    scores_.reserve(wall.hold_count());
  }

  std::span<const double> of(const ClimbingMdp& mdp, const DeterministicModel& experience,
                             std::span<const ActionCandidate> candidates) {
    const StateCode state = mdp.state().wall;
    holds_.clear();
    failed_.clear();
    for (const ActionCandidate& c : candidates) {
      holds_.push_back(c.wall);
      const Experience* known = experience.find(state, c.wall);
      if (known != nullptr && known->next_wall_state == state) failed_.push_back(c.wall);
    }
    forward_kinematics(model_, workspace_.body, mdp.posture());
    const Eigen::Vector3d centre = centre_of_mass(model_, workspace_.body);
    scores_.resize(candidates.size());
    score_candidates(model_, network_, workspace_,
                     {mdp.wall(), mdp.configuration(), mdp.posture(), centre, holds_, max_span_m_, failed_}, scores_);
    return scores_;
  }

 private:
  const BodyModel& model_;
  const PolicyNetwork& network_;
  PolicyWorkspace workspace_;  // its body data also gives the centre of mass the observation reads
  double max_span_m_;
  std::vector<int> holds_, failed_;
  std::vector<double> scores_;
};

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
      if (q_wall.value(mdp.state().wall, candidates[i].wall) > q_wall.value(mdp.state().wall, candidates[best].wall))
        best = i;
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

constexpr std::uint64_t kStateVersion = 2;  // 2: each record says whether the climber fell

void save_postures(CheckpointWriter& out, const std::vector<Posture>& postures) {
  out.value<std::uint64_t>(postures.size());
  for (const Posture& p : postures) save_posture(out, p);
}

std::vector<Posture> load_postures(CheckpointReader& in) {
  const std::uint64_t count = in.value<std::uint64_t>();
  std::vector<Posture> postures;
  for (std::uint64_t i = 0; i < count; ++i) postures.push_back(load_posture(in));
  return postures;
}

// The loop's own state besides the agent and the MDP.
struct LoopState {
  int iteration = 0, episode = 0, episode_start = 0;
};

// Records field by field: no padding bytes reach the file.
void save_records(CheckpointWriter& out, const std::vector<IterationRecord>& records) {
  out.value<std::uint64_t>(records.size());
  for (const IterationRecord& r : records) {
    out.value(r.episode);
    out.value(static_cast<std::int32_t>(r.regime));
    out.value(r.hold_id);
    out.value<std::uint8_t>(r.success ? 1 : 0);
    out.value<std::uint8_t>(r.fell ? 1 : 0);
    out.value(r.root_rise_m);
    out.value(r.reward);
    out.value(r.grid_state);
    out.value(r.tile);
    out.value(r.tile_offset_y);
    out.value(r.tile_offset_z);
    out.value<std::uint8_t>(r.back_to_left_hold ? 1 : 0);
  }
}

void load_records(CheckpointReader& in, std::vector<IterationRecord>& records) {
  const std::uint64_t count = in.value<std::uint64_t>();
  if (count > records.capacity()) in.fail();
  for (std::uint64_t i = 0; i < count; ++i) {
    IterationRecord r;
    r.episode = in.value<int>();
    const std::int32_t regime = in.value<std::int32_t>();
    if (regime < 0 || regime >= kRegimeCount) in.fail();
    r.regime = static_cast<Regime>(regime);
    r.hold_id = in.value<int>();
    r.success = in.flag();
    r.fell = in.flag();
    r.root_rise_m = in.value<double>();
    r.reward = in.value<double>();
    r.grid_state = in.value<std::uint32_t>();
    r.tile = in.value<ActionCode>();
    r.tile_offset_y = in.value<float>();
    r.tile_offset_z = in.value<float>();
    r.back_to_left_hold = in.flag();
    records.push_back(r);
  }
}

std::string save_state(const LoopState& loop, const RunResult& result, const std::vector<Posture>& climb,
                       const DynaQAgent& agent, const ClimbingMdp& mdp) {
  CheckpointWriter out;
  out.value(kStateVersion);
  out.value(loop);
  save_records(out, result.iterations);
  out.vector(result.episode_lengths);
  save_postures(out, result.last_climb);
  save_postures(out, climb);
  agent.save_state(out);
  mdp.save_state(out);
  return out.take();
}

LoopState load_state(const RunCheckpoints& checkpoints, int iterations, RunResult& result, std::vector<Posture>& climb,
                     DynaQAgent& agent, ClimbingMdp& mdp) {
  CheckpointReader in(checkpoints.resume, checkpoints.source);
  if (in.value<std::uint64_t>() != kStateVersion) in.fail();
  const LoopState loop = in.value<LoopState>();
  if (loop.iteration < 0 || loop.iteration > iterations || loop.episode < 0 || loop.episode_start < 0 ||
      loop.episode_start > loop.iteration) {
    in.fail();
  }
  load_records(in, result.iterations);
  if (result.iterations.size() != static_cast<std::size_t>(loop.iteration)) in.fail();
  result.episode_lengths = in.vector<int>();
  if (result.episode_lengths.size() != static_cast<std::size_t>(loop.episode)) in.fail();
  result.last_climb = load_postures(in);
  climb = load_postures(in);
  agent.load_state(in);
  mdp.load_state(in);
  if (!in.at_end()) in.fail();
  return loop;
}

}  // namespace

RunResult run_learning(const BodyModel& model, const Wall& wall, const LearningParameters& parameters,
                       std::uint64_t seed, const QTable* initial_q_grid, const std::function<void(int)>& progress,
                       const RunCheckpoints* checkpoints, const PolicyNetwork* policy) {
  ClimbingMdp mdp(model, wall, parameters.climbing, parameters.dyna.rates.gamma);
  DynaQAgent agent(mdp.wall_action_count(), mdp.grid_action_count(), parameters.dyna, seed);
  if (initial_q_grid != nullptr) agent.set_q_grid(*initial_q_grid);
  std::optional<CandidateScores> scores;
  if (policy != nullptr && parameters.dyna.transfer == TransferMode::Network)
    scores.emplace(model, *policy, wall, parameters.climbing.filter.max_span_m);
  RunResult result;
  result.can_fall = checks_stances(parameters.climbing.physics.model);
  result.iterations.reserve(parameters.iterations);
  std::vector<Posture> climb{mdp.posture()};
  LoopState loop;
  if (checkpoints != nullptr && !checkpoints->resume.empty()) {
    loop = load_state(*checkpoints, parameters.iterations, result, climb, agent, mdp);
    if (checkpoints->resumed) checkpoints->resumed(loop.iteration);
  } else {
    agent.observe(mdp.state(), mdp.candidates());
  }
  int& episode = loop.episode;
  int& episode_start = loop.episode_start;
  for (int& iteration = loop.iteration; iteration < parameters.iterations;) {
    const StateCouple state = mdp.state();
    const std::span<const ActionCandidate> candidates = mdp.candidates();
    const ActionChoice choice = agent.choose(
        state, candidates, scores ? scores->of(mdp, agent.model(), candidates) : std::span<const double>());
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
    record.fell = outcome.fell;
    record.root_rise_m = outcome.root_rise_m;
    record.reward = outcome.reward;
    result.iterations.push_back(record);
    if (outcome.reached) climb.push_back(*outcome.posture);
    if (outcome.fell) climb.assign(1, mdp.posture());  // the episode's climb starts again
    if (outcome.finished) {
      result.episode_lengths.push_back(iteration + 1 - episode_start);
      episode_start = iteration + 1;
      ++episode;
      result.last_climb = std::move(climb);
      climb.assign(1, mdp.posture());
    }
    ++iteration;
    if (progress) progress(iteration);
    if (checkpoints != nullptr && checkpoints->every > 0 && iteration % checkpoints->every == 0 &&
        iteration < parameters.iterations) {
      checkpoints->save(save_state(loop, result, climb, agent, mdp), iteration);
    }
  }
  result.reached_configurations = mdp.reacher().cache().reached_count();
  result.unreachable_configurations = mdp.reacher().cache().unreachable_count();
  result.ik_solves = mdp.reacher().solves();
  greedy_climb(mdp, agent.q_wall(), parameters.greedy_cap, result);
  result.simulates = mdp.simulates();
  result.moves_simulated = mdp.moves_simulated();
  result.moves_performed = mdp.moves_performed();
  result.q_grid = agent.q_grid();
  result.explored_pairs = agent.model().size();
  result.planning_updates = agent.planning_updates();
  return result;
}

}  // namespace crux
