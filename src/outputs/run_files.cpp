#include "outputs/run_files.hpp"

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "learning/q_table_file.hpp"
#include "outputs/iterations_file.hpp"
#include "outputs/posture_csv.hpp"

namespace crux {

void write_run_files(const std::filesystem::path& directory, const RunResult& run, const BodyModel& model,
                     const GridParameters& grid) {
  make_output_directory(directory);
  std::string iterations = run.can_fall ? kIterationsHeaderWithFalls : kIterationsHeader;
  iterations += '\n';
  for (std::size_t i = 0; i < run.iterations.size(); ++i) {
    const IterationRecord& r = run.iterations[i];
    iterations += fmt::format("{},{},{},{},{},{},{}", i + 1, r.episode, enum_name(r.regime), r.hold_id,
                              r.success ? 1 : 0, 100.0 * r.root_rise_m, r.reward);
    iterations += run.can_fall ? (r.fell ? ",1\n" : ",0\n") : "\n";
  }
  write_file_atomically(directory / "iterations.csv", iterations);
  std::string episodes = "episode,length\n";
  for (std::size_t e = 0; e < run.episode_lengths.size(); ++e) {
    episodes += fmt::format("{},{}\n", e, run.episode_lengths[e]);
  }
  write_file_atomically(directory / "episodes.csv", episodes);
  save_q_table((directory / "q_grid.bin").string(), run.q_grid, describe_grid(grid));
  write_file_atomically(directory / "climb.csv", posture_csv(model, run.last_climb, "step"));
  // The start row has no move: hold 0, reward 0.
  PostureCsvColumn holds{"hold", {"0"}}, rewards{"reward", {"0"}};
  for (const ClimbMove& move : run.greedy_moves) {
    holds.cells.push_back(fmt::format("{}", move.hold_id));
    rewards.cells.push_back(fmt::format("{}", move.reward));
  }
  write_file_atomically(directory / "greedy_climb.csv", posture_csv(model, run.greedy_climb, "step", {holds, rewards}));
}

}  // namespace crux
