// crux paper, train, transfer and plan end to end.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "support/fifo_reader.hpp"
#include "support/run_crux.hpp"
#include "support/test_models.hpp"
#include "support/trained_run.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;
using testing::run_crux;

fs::path learning_scratch(const std::string& name) {
  const fs::path dir = testing::test_folder() / "learning-cli";
  fs::create_directories(dir);
  return dir / name;
}

TEST(CliLearning, ShortPaperRunWritesTheOutputFolder) {
  const fs::path out = learning_scratch("paper");
  const auto outcome = run_crux("paper --runs 1 --iterations 300 --plan=false --seed 5 -o " + out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("Table I"), std::string::npos);
  for (const char* file :
       {"config.toml", "summary.json", "runs/training_0/iterations.csv", "runs/transfer_0/episodes.csv",
        "runs/control_0/q_grid.bin", "runs/training_0/climb.csv", "walls/transfer_0.json", "figures/fig3_regimes.csv",
        "figures/fig4_episode_lengths.csv", "figures/fig2b_qgrid_maps.csv"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_TRUE(summary["table1"]["control"]["overall"]["random"].contains("success_rate"));
  for (const auto& entry : fs::recursive_directory_iterator(out)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << "no temporary file left";
  }
}

TEST(CliLearning, TrainThenTransferFromItsQGrid) {
  const fs::path train = learning_scratch("train"), transfer = learning_scratch("transfer");
  const auto trained = run_crux("train --wall-seed 3 --iterations 300 -o " + train.string());
  ASSERT_EQ(trained.exit_code, 0) << trained.err;
  const auto transferred = run_crux("transfer --q-grid " + (train / "q_grid.bin").string() +
                                    " --wall-seed 4 --iterations 300 -o " + transfer.string());
  ASSERT_EQ(transferred.exit_code, 0) << transferred.err;
  std::ifstream in(transfer / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["kind"], "run");
  EXPECT_EQ(summary["provenance"]["q_grid"], fs::absolute(train / "q_grid.bin").lexically_normal().string());
  EXPECT_EQ(summary["provenance"]["q_grid_sha256"].get<std::string>().size(), 64u);
  EXPECT_EQ(summary["provenance"]["wall_seed"], 4);
  EXPECT_EQ(summary["episode_lengths"]["transfer"].size(), 1u);
}

TEST(CliLearning, BadQGridIsOneLineExit2AndWritesNothing) {
  const auto bad = testing::write_temporary("cli_bad_qgrid.bin", "CRUXQTAB\x01");
  const fs::path out = learning_scratch("never");
  const auto outcome = run_crux("transfer --q-grid " + bad.string() + " --wall-seed 4 -o " + out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(testing::count_lines(outcome.err), 1) << outcome.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliLearning, ConfigFileAndFlagsCombine) {
  const auto config = testing::write_temporary("cli_config.toml", "[experiment]\niterations = 250\nseed = 9\n");
  const fs::path out = learning_scratch("configured");
  const auto outcome = run_crux("train --wall-seed 3 --config " + config.string() + " --seed 11 -o " + out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  std::ifstream in(out / "config.toml");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("iterations = 250"), std::string::npos) << "from the file";
  EXPECT_NE(text.find("seed = 11"), std::string::npos) << "the flag overrides the file";
}

TEST(CliLearning, TrainUnderTheNetworkModeRecordsThePolicyItWasOrderedBy) {
  const auto policy = testing::write_temporary("cli_height_policy.json", testing::linear_policy_json(57, 1.0));
  const fs::path out = learning_scratch("network");
  const auto outcome = run_crux("train --wall-seed 3 --iterations 300 --transfer network --policy " + policy.string() +
                                " -o " + out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["provenance"]["policy"], fs::absolute(policy).lexically_normal().string());
  EXPECT_EQ(summary["provenance"]["policy_sha256"].get<std::string>().size(), 64u);
  const fs::path replay = learning_scratch("network_replay");
  const auto replayed = run_crux("train --config " + (out / "config.toml").string() + " -o " + replay.string());
  ASSERT_EQ(replayed.exit_code, 0) << replayed.err;
  const auto text = [](const fs::path& file) {
    std::ifstream file_in(file);
    return std::string((std::istreambuf_iterator<char>(file_in)), std::istreambuf_iterator<char>());
  };
  EXPECT_EQ(text(out / "iterations.csv"), text(replay / "iterations.csv"));
}

// Each: one line naming the input, exit code 2, no folder written.
TEST(CliLearning, BadPolicyInputsAreOneLineExit2AndWriteNothing) {
  const auto corrupt = testing::write_temporary("cli_corrupt_policy.json", "{\"format\": \"crux-policy\", ");
  const auto numeric = testing::write_temporary(
      "cli_numeric_policy.json", testing::replaced(testing::linear_policy_json(57, 1.0), "\"reach\"", "\"numeric\""));
  const auto other_span = testing::write_temporary("cli_span_policy.json", testing::linear_policy_json(57, 1.0, 3.5));
  const auto good = testing::write_temporary("cli_good_policy.json", testing::linear_policy_json(57, 1.0));
  const std::string missing = testing::temporary_path("cli_missing_policy.json").string();
  const std::string train = "train --wall-seed 3 --iterations 50 ";
  const std::vector<std::pair<std::string, std::string>> cases{
      {train + "--transfer network --policy " + missing, missing + ": no such file"},
      {train + "--transfer network --policy " + corrupt.string(), corrupt.string() + ": not JSON"},
      {train + "--transfer network --policy " + numeric.string(), "a policy for the \"numeric\" observation"},
      {train + "--transfer network --policy " + other_span.string(), "filter.max_span = 3.5 m"},
      {train + "--transfer network", "--policy: experiment.transfer = network orders exploration"},
      {train + "--transfer ordered --policy " + good.string(), "only experiment.transfer = network uses a policy"},
      {"paper --transfer network --walls 2 --iterations 50", "--transfer: network orders exploration by"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const fs::path out = learning_scratch(fmt::format("bad_policy_{}", i));
    const auto outcome = run_crux(cases[i].first + " -o " + out.string());
    EXPECT_EQ(outcome.exit_code, 2) << cases[i].first << ": " << outcome.err;
    EXPECT_EQ(testing::count_lines(outcome.err), 1) << outcome.err;
    EXPECT_NE(outcome.err.find(cases[i].second), std::string::npos) << outcome.err;
    EXPECT_FALSE(fs::exists(out)) << cases[i].first;
  }
}

TEST(CliLearning, PlanReportsItsLength) {
  const auto outcome = run_crux("plan --wall-seed 3 --json");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto json = nlohmann::json::parse(outcome.out);
  EXPECT_GT(json["length"].get<int>(), 0);
  EXPECT_EQ(json["holds"].size(), json["length"].get<std::size_t>());
}

// The repository's large boards: the search ends at its budget, says so, and names the flag.
TEST(CliLearning, PlanOnALargeBoardStopsAtItsLimit) {
  const auto board = fs::path(CRUX_SOURCE_DIR) / "walls" / "board_140.json";
  const auto text = run_crux("plan --plan-max-solves 3000 --wall-file " + board.string());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("within 3000 IK solves"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("--plan-max-solves"), std::string::npos) << text.out;
  const auto json =
      nlohmann::json::parse(run_crux("plan --plan-max-solves 3000 --json --wall-file " + board.string()).out);
  EXPECT_FALSE(json["found"].get<bool>());
  EXPECT_TRUE(json["stopped_at_limit"].get<bool>());
  EXPECT_EQ(json["ik_solves"].get<int>(), 3000);
}

TEST(CliLearning, MissingWallIsExplained) {
  const auto outcome = run_crux("plan");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_NE(outcome.err.find("--wall-file"), std::string::npos);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every file of `first` has a twin in `second` with the same bytes, summary.json included.
void expect_same_folder(const fs::path& first, const fs::path& second) {
  int compared = 0;
  for (const auto& entry : fs::recursive_directory_iterator(first)) {
    if (!entry.is_regular_file()) continue;
    const fs::path twin = second / fs::relative(entry.path(), first);
    ASSERT_TRUE(fs::exists(twin)) << twin;
    EXPECT_EQ(read_text(entry.path()), read_text(twin)) << twin;
    ++compared;
  }
  EXPECT_GE(compared, 7);
}

TEST(CliLearning, TrainAndTransferReplayFromTheirOwnConfig) {
  const fs::path wall = learning_scratch("replay_wall.json");
  ASSERT_EQ(run_crux("wall generate --wall-seed 6 -o " + wall.string()).exit_code, 0);
  const fs::path train = learning_scratch("replay_train"), train_again = learning_scratch("replay_train_again");
  ASSERT_EQ(
      run_crux("train --wall-seed 3 --iterations 200 --seed 4 --learning-epsilon 0.2 -o " + train.string()).exit_code,
      0);
  const auto replayed = run_crux("train --config " + (train / "config.toml").string() + " -o " + train_again.string());
  ASSERT_EQ(replayed.exit_code, 0) << replayed.err;
  expect_same_folder(train, train_again);
  const fs::path transfer = learning_scratch("replay_transfer"),
                 transfer_again = learning_scratch("replay_transfer_again");
  ASSERT_EQ(run_crux("transfer --q-grid " + (train / "q_grid.bin").string() + " --wall-file " + wall.string() +
                     " --iterations 200 -o " + transfer.string())
                .exit_code,
            0);
  const std::string config = read_text(transfer / "config.toml");
  EXPECT_NE(config.find("wall_sha256 = "), std::string::npos);
  EXPECT_NE(config.find("q_grid_sha256 = "), std::string::npos);
  EXPECT_NE(config.find("urdf_sha256 = "), std::string::npos);
  EXPECT_NE(config.find("crux_version = "), std::string::npos);
  const auto again =
      run_crux("transfer --config " + (transfer / "config.toml").string() + " -o " + transfer_again.string());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  expect_same_folder(transfer, transfer_again);
  // A replay whose input changed since is refused, naming the config and the digest.
  std::ofstream(wall, std::ios::app) << "\n";
  const auto changed = run_crux("transfer --config " + (transfer / "config.toml").string() + " -o " +
                                learning_scratch("replay_changed").string());
  EXPECT_EQ(changed.exit_code, 2);
  EXPECT_NE(changed.err.find("provenance.wall_sha256"), std::string::npos) << changed.err;
  EXPECT_EQ(testing::count_lines(changed.err), 1) << changed.err;
}

TEST(CliLearning, PaperReplaysFromItsOwnConfig) {
  const fs::path first = learning_scratch("replay_paper"), second = learning_scratch("replay_paper_again");
  ASSERT_EQ(run_crux("paper --walls 1 --seeds-per-wall 2 --iterations 150 --plan false --seed 8 -o " + first.string())
                .exit_code,
            0);
  const auto replayed = run_crux("paper --config " + (first / "config.toml").string() + " -o " + second.string());
  ASSERT_EQ(replayed.exit_code, 0) << replayed.err;
  expect_same_folder(first, second);
}

TEST(CliLearning, AnOutputFolderIsNeitherMixedWithEarlierOutputsNorAnInputsHome) {
  const fs::path folder = learning_scratch("guarded");
  ASSERT_EQ(run_crux("train --wall-seed 3 --iterations 100 -o " + folder.string()).exit_code, 0);
  EXPECT_FALSE(fs::exists(folder / "INCOMPLETE")) << "a complete folder loses its marker";
  const std::string first = read_text(folder / "iterations.csv");
  const auto again = run_crux("train --wall-seed 3 --iterations 100 --seed 2 -o " + folder.string());
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("already holds files"), std::string::npos) << again.err;
  EXPECT_EQ(read_text(folder / "iterations.csv"), first) << "nothing touched";
  // Its own input: refused even when asked to overwrite.
  const auto own_input = run_crux("transfer --q-grid " + (folder / "q_grid.bin").string() +
                                  " --wall-seed 4 --iterations 100 --overwrite -o " + folder.string());
  EXPECT_EQ(own_input.exit_code, 2);
  EXPECT_NE(own_input.err.find("an input of this command"), std::string::npos) << own_input.err;
  EXPECT_TRUE(fs::exists(folder / "q_grid.bin"));
  const fs::path other = folder / "notes.txt";
  std::ofstream(other) << "mine";
  const auto replaced = run_crux("train --wall-seed 3 --iterations 100 --seed 2 --overwrite -o " + folder.string());
  ASSERT_EQ(replaced.exit_code, 0) << replaced.err;
  EXPECT_NE(read_text(folder / "iterations.csv"), first);
  EXPECT_EQ(read_text(other), "mine") << "only crux's outputs are replaced";
}

TEST(CliLearning, EachCommandRefusesTheFlagsItDoesNotUse) {
  for (const char* command :
       {"plan --wall-seed 3 --iterations 5", "plan --wall-seed 3 --runs 100", "train --wall-seed 3 --plan 0",
        "train --wall-seed 3 --runs 3", "train --wall-seed 3 --threads 2", "paper --wall-seed 3",
        "ik-compare --ik-solver fast", "model --iterations 3"}) {
    const auto outcome = run_crux(command);
    EXPECT_EQ(outcome.exit_code, 2) << command;
    EXPECT_NE(outcome.err.find("unknown option --"), std::string::npos) << command << ": " << outcome.err;
    EXPECT_EQ(testing::count_lines(outcome.err), 1) << outcome.err;
  }
  const auto typo = run_crux("train --wall-seed 3 --iteration 5");
  EXPECT_NE(typo.err.find("did you mean '--iterations'?"), std::string::npos) << typo.err;
  const auto config = testing::write_temporary("cli_plan_config.toml", "[experiment]\niterations = 5\n");
  const auto from_file = run_crux("plan --wall-seed 3 --config " + config.string());
  EXPECT_EQ(from_file.exit_code, 2);
  EXPECT_NE(from_file.err.find(config.string() + ": line 2: crux plan does not take experiment.iterations"),
            std::string::npos)
      << from_file.err;
}

TEST(CliLearning, ErrorsNameTheFlagOrTheFileAndKeyTheUserTyped) {
  const auto runs = run_crux("paper --runs 0");
  EXPECT_EQ(runs.exit_code, 2);
  EXPECT_EQ(runs.err, "crux: --runs: must be from 1 to 1000000\n");
  const auto beginning = run_crux("train --wall-seed 3 --iterations 100 --beginning 200");
  EXPECT_EQ(beginning.exit_code, 2);
  EXPECT_EQ(beginning.err.rfind("crux: --beginning: must not exceed", 0), 0u) << beginning.err;
  const auto config = testing::write_temporary("cli_bad_gamma.toml", "[learning]\n\ngamma = 1.5\n");
  const auto from_file = run_crux("train --wall-seed 3 --config " + config.string());
  EXPECT_EQ(from_file.exit_code, 2);
  EXPECT_EQ(from_file.err, "crux: " + config.string() + ": line 3: learning.gamma: must be in [0, 1)\n");
  const fs::path never = learning_scratch("never_written");
  const auto not_finite = run_crux("train --wall-seed 3 --wall-finish-height nan -o " + never.string());
  EXPECT_EQ(not_finite.err, "crux: --wall-finish-height: must be a finite number\n");
  EXPECT_FALSE(fs::exists(never)) << "nothing written before the input is checked";
  const auto no_start = run_crux("paper --walls 1 --iterations 10 --wall-sigma 3 -o " + never.string());
  EXPECT_EQ(no_start.exit_code, 2);
  EXPECT_EQ(
      no_start.err,
      "crux: --wall-* and --ik-* parameters: no random wall drawn with them has a reachable start (1000 tried)\n");
  EXPECT_FALSE(fs::exists(never)) << "nothing written when the run fails";
  // Under the static model its parameters can refuse every start too, and are named.
  const auto no_static_start =
      run_crux("paper --walls 1 --iterations 10 --wall-sigma 3 --physics-model static -o " + never.string());
  EXPECT_EQ(no_static_start.err.rfind("crux: --wall-*, --ik-* and --physics-* parameters: no random wall", 0), 0u)
      << no_static_start.err;
  EXPECT_FALSE(fs::exists(never));
  const auto seed = run_crux("train --wall-seed -1");
  EXPECT_EQ(seed.exit_code, 2);
  EXPECT_NE(seed.err.find("--wall-seed"), std::string::npos) << seed.err;
  const auto unknown = run_crux("trian");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("unknown command 'trian' (did you mean 'train'?)"), std::string::npos) << unknown.err;
  const auto nested = run_crux("wall gen");
  EXPECT_NE(nested.err.find("(did you mean 'wall generate'?)"), std::string::npos) << nested.err;
}

// Under the static model a climber can fall back to the start in the middle of an episode
// (docs/MODEL.md, C27 and C31); climb.csv then holds the episode's last attempt, and the
// report replays it. Wall 5 with learning seed 3 falls six times in its last episode.
TEST(CliLearning, AStaticRunWhoseLastClimbFellIsReportedFromItsLastAttempt) {
  const fs::path run = learning_scratch("static_falls");
  fs::remove_all(run);
  const auto trained = run_crux(
      "train --wall-seed 5 --seed 3 --iterations 3000 --physics-model static --transfer seeded --reward-height 100 "
      "--physics-fall-when-stuck true -o " +
      run.string());
  ASSERT_EQ(trained.exit_code, 0) << trained.err;
  std::ifstream episodes_in(run / "episodes.csv");
  int completed = -1;  // the header
  for (std::string line; std::getline(episodes_in, line);) ++completed;
  ASSERT_GE(completed, 1);
  std::ifstream iterations_in(run / "iterations.csv");
  std::string line;
  std::getline(iterations_in, line);
  ASSERT_EQ(line, "iteration,episode,regime,hold,success,root_rise_cm,reward,fell");
  int falls = 0, moves_since_fall = 0;
  while (std::getline(iterations_in, line)) {
    std::vector<std::string> cells;
    for (std::size_t start = 0, end = 0; end != std::string::npos; start = end + 1) {
      end = line.find(',', start);
      cells.push_back(line.substr(start, end - start));
    }
    if (std::stoi(cells[1]) != completed - 1) continue;
    ++moves_since_fall;
    if (cells[7] == "1") ++falls, moves_since_fall = 0;
  }
  ASSERT_GT(falls, 0) << "the last completed episode must fall for this test to check anything";
  const auto report =
      run_crux("report " + run.string() + " -o " + learning_scratch("static_falls_report").string() + " --json");
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const auto json = nlohmann::json::parse(report.out);
  EXPECT_EQ(json.at("replay_climb"), "last");
  EXPECT_EQ(json.at("climb_moves"), moves_since_fall);
  // Which attempt of which episode it shows: the one after the episode's last fall.
  EXPECT_EQ(json.at("replay_episode"), completed);
  EXPECT_EQ(json.at("replay_attempt"), falls + 1);
  EXPECT_NE(json.at("replay_reason")
                .get<std::string>()
                .find(fmt::format("it shows the episode's last attempt, attempt {}, after {} fall", falls + 1, falls)),
            std::string::npos)
      << json.at("replay_reason");
  // The same episode asked by number says the same.
  const auto numbered = run_crux("report " + run.string() + " --climb " + std::to_string(completed) + " -o " +
                                 learning_scratch("static_falls_numbered").string() + " --json");
  ASSERT_EQ(numbered.exit_code, 0) << numbered.err;
  EXPECT_EQ(nlohmann::json::parse(numbered.out).at("replay_attempt"), falls + 1);
}

TEST(CliLearning, TrainingWallsOutsideTheirRangeAreOneLine) {
  for (const char* count : {"0", "1001"}) {
    const auto outcome = run_crux(std::string("paper --training-walls ") + count);
    EXPECT_EQ(outcome.exit_code, 2);
    EXPECT_EQ(outcome.err, "crux: --training-walls: must be from 1 to 1000\n");
  }
}

TEST(CliLearning, PaperWithTrainingWallsReportsTheTotalIterations) {
  const fs::path folder = learning_scratch("training_walls");
  fs::remove_all(folder);
  const auto outcome =
      run_crux("paper --walls 1 --training-walls 2 --iterations 150 --plan false -o " + folder.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find(
                "Iterations spent per transfer run: training over 2 walls 300, transfer 150, total 450; control 150"),
            std::string::npos)
      << outcome.out;
  std::ifstream in(folder / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(in)["iterations_spent"]["total"], 450);
}

TEST(CliLearning, TrainingWallKeysAreCheckedAsTheWallKeys) {
  auto outcome = run_crux("paper --training-wall-sigma -0.1");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.err, "crux: --training-wall-sigma: must be in [0, 10]\n");
  outcome = run_crux("paper --training-wall-rows 2");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.err, "crux: --training-wall-rows: must reach the start holds (at least 3 tiles)\n");
  outcome = run_crux("paper --training-wall-tile-width nan");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(testing::count_lines(outcome.err), 1) << outcome.err;
  EXPECT_NE(outcome.err.find("--training-wall-tile-width"), std::string::npos) << outcome.err;
}

// The section is written only when set, and the written config.toml replays it.
TEST(CliLearning, PaperWithTrainingWallsOfTheirOwnReplaysFromItsConfig) {
  const fs::path folder = learning_scratch("training_wall"), again = learning_scratch("training_wall_again");
  fs::remove_all(folder);
  fs::remove_all(again);
  const auto outcome =
      run_crux("paper --walls 1 --iterations 150 --plan false --training-wall-sigma 0.16 -o " + folder.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(read_text(folder / "config.toml").find("[training_wall]\nsigma = 0.16  #"), std::string::npos);
  ASSERT_EQ(run_crux("paper --config " + (folder / "config.toml").string() + " -o " + again.string()).exit_code, 0);
  for (const char* file : {"walls/training_0.json", "walls/transfer_0.json", "runs/training_0/iterations.csv"}) {
    EXPECT_EQ(read_text(again / file), read_text(folder / file)) << file;
  }
}

TEST(CliLearning, AnUnknownAgentSpaceIsOneLine) {
  const auto outcome = run_crux("paper --grid-agent-space hexagons");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.err, "crux: --grid-agent-space: unknown agent space 'hexagons' (expected grid or reach)\n");
}

TEST(CliLearning, TheReachAgentSpaceLearnsAndRefusesAGridsQGrid) {
  const fs::path train = learning_scratch("reach_train"), transfer = learning_scratch("reach_transfer"),
                 never = learning_scratch("reach_never"), reach_train = learning_scratch("reach_train_reach");
  for (const fs::path& folder : {train, transfer, reach_train}) fs::remove_all(folder);
  const std::string reach = " --grid-agent-space reach --grid-columns 8 --grid-rows 4 --grid-tile-height 0.3";
  ASSERT_EQ(run_crux("train --wall-seed 3 --iterations 300 -o " + train.string()).exit_code, 0);
  const std::string q_grid = (train / "q_grid.bin").string();
  const auto refused =
      run_crux("transfer --q-grid " + q_grid + " --wall-seed 4 --iterations 300" + reach + " -o " + never.string());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.err, "crux: " + q_grid + ": the table has 35 actions where 32 are expected (a different grid?)\n");
  const auto same_shape = run_crux("transfer --q-grid " + q_grid +
                                   " --wall-seed 4 --iterations 300 --grid-agent-space reach -o " + never.string());
  EXPECT_EQ(same_shape.exit_code, 2);
  EXPECT_EQ(same_shape.err.rfind("crux: " + q_grid + ": the table was learnt on a 5 x 7 moving grid", 0), 0u)
      << same_shape.err;
  EXPECT_NE(same_shape.err.find("this run uses reach sectors: 5 directions x 7 rings"), std::string::npos)
      << same_shape.err;
  EXPECT_EQ(testing::count_lines(same_shape.err), 1);
  EXPECT_FALSE(fs::exists(never));
  // Learnt under the reach space, the table transfers under it.
  ASSERT_EQ(run_crux("train --wall-seed 3 --iterations 300" + reach + " -o " + reach_train.string()).exit_code, 0);
  const auto transferred = run_crux("transfer --q-grid " + (reach_train / "q_grid.bin").string() +
                                    " --wall-seed 4 --iterations 300" + reach + " -o " + transfer.string());
  ASSERT_EQ(transferred.exit_code, 0) << transferred.err;
}

TEST(CliLearning, ViewAndReportAnswerBadInputWithOneLine) {
  const fs::path never = learning_scratch("never_report.html");
  const auto no_folder = run_crux("report /nonexistent/crux_folder -o " + never.string());
  EXPECT_EQ(no_folder.exit_code, 2);
  EXPECT_EQ(no_folder.err, "crux: /nonexistent/crux_folder: no such output folder\n");
  // A folder of the test's own that holds no run (the shared temporary folder may hold anything).
  const fs::path empty = learning_scratch("not_a_run");
  fs::create_directories(empty);
  const auto no_run = run_crux("view --run " + empty.string() + " -o " + never.string());
  EXPECT_EQ(no_run.exit_code, 2);
  EXPECT_NE(no_run.err.find("not a run folder"), std::string::npos) << no_run.err;
  EXPECT_EQ(testing::count_lines(no_run.err), 1);
  const auto both = run_crux("view -o x.svg");
  EXPECT_EQ(both.err, "crux: --run: give a run folder (--run DIR) or a wall file (--wall-file FILE)\n");
  EXPECT_FALSE(fs::exists(never));
}

// Issue 25: `report RUN -o ''` failed naming no flag.
TEST(CliLearning, ReportToAnEmptyOutputNamesTheFlag) {
  const auto outcome = run_crux("report " + testing::trained_run_folder().string() + " -o ''");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.err, "crux: --output: the output file name is empty\n");
}

// Issue 25: --threads 100000 aborted crux sweep, leaving INCOMPLETE, crux paper clamped it
// silently, and --iterations 2147483647 ended in bad_alloc: every command that takes them
// (paper and sweep take --threads) refuses a value above the bound before it creates its
// output folder.
TEST(CliLearning, ThreadsAndIterationsAboveTheirBoundsAreRefusedBeforeAnyOutput) {
  const std::string threads = "crux: --threads: must be from 0 to 1024 (0: all cores)\n";
  const std::string iterations =
      "crux: --iterations: must be from 1 to 10000000 (a run keeps every iteration's record in memory)\n";
  const fs::path config = testing::write_temporary("bounds.toml", "[experiment]\nthreads = 1025\n");
  const std::vector<std::pair<std::string, std::string>> cases{
      {"paper --threads 1025", threads},
      {"sweep --threads 100000", threads},
      {"sweep --config " + config.string(), "crux: " + config.string() +
                                                ": line 2: experiment.threads: must be from 0 "
                                                "to 1024 (0: all cores)\n"},
      {"paper --iterations 10000001", iterations},
      {"sweep --iterations 2147483647", iterations},
      {"train --wall-seed 3 --iterations 2147483647", iterations},
  };
  for (const auto& [arguments, error] : cases) {
    const fs::path out = learning_scratch("bounds-out");
    fs::remove_all(out);
    const auto outcome = run_crux(arguments + " -o " + out.string());
    EXPECT_EQ(outcome.exit_code, 2) << arguments;
    EXPECT_EQ(outcome.err, error) << arguments;
    EXPECT_FALSE(fs::exists(out)) << arguments << ": a refusal leaves no folder, so no INCOMPLETE";
  }
}

// -o naming the command's own input (a file of the run folder it reads, the wall file,
// the --config file) is refused before any work, in one line naming --output, and the
// input is left as it was.
TEST(CliLearning, AnOutputFileNamingAnInputOfTheCommandIsRefused) {
  // A copy: without the check, the commands below would overwrite the shared trained run.
  const fs::path run = testing::edited_trained_run("output-is-input", "summary.json", [](std::string&) {});
  const std::string summary = read_text(run / "summary.json"), wall = read_text(run / "wall.json");
  const auto report = run_crux("report " + run.string() + " -o " + (run / "summary.json").string());
  EXPECT_EQ(report.exit_code, 2);
  EXPECT_EQ(report.err, "crux: --output: " + (run / "summary.json").string() + " would overwrite " + run.string() +
                            ", an input of this command; write to another file\n");
  const auto view = run_crux("view --run " + run.string() + " -o " + (run / "wall.json").string());
  EXPECT_EQ(view.exit_code, 2);
  EXPECT_EQ(testing::count_lines(view.err), 1) << view.err;
  EXPECT_NE(view.err.find("crux: --output: "), std::string::npos) << view.err;
  // Named relative to where crux runs, the same file however it is spelt.
  const auto show = testing::run_crux_in(run, "wall show --wall-file wall.json -o ./wall.json");
  EXPECT_EQ(show.exit_code, 2);
  EXPECT_EQ(show.err,
            "crux: --output: ./wall.json would overwrite wall.json, an input of this command; write to "
            "another file\n");
  const fs::path config = testing::write_temporary("cli_output_is_config.toml", "[wall]\nseed = 4\n");
  const auto generate = run_crux("wall generate --config " + config.string() + " -o " + config.string());
  EXPECT_EQ(generate.exit_code, 2);
  EXPECT_NE(generate.err.find("would overwrite " + config.string()), std::string::npos) << generate.err;
  EXPECT_EQ(read_text(config), "[wall]\nseed = 4\n");
  EXPECT_EQ(read_text(run / "summary.json"), summary);
  EXPECT_EQ(read_text(run / "wall.json"), wall);
  const auto empty = run_crux("report " + run.string() + " -o ''");
  EXPECT_EQ(empty.err, "crux: --output: the output file name is empty\n");
}

// Issue 25: a report's page grew with the replayed climb without a bound (a 60,000-move
// episode made a 173 MB page). The replay shows the first --replay-moves moves, and the
// page, the text and --json say when the climb has more; a value outside 1..20000 is
// refused before anything is written.
TEST(CliLearning, AReportReplaysAtMostReplayMovesAndSaysSo) {
  const fs::path train = testing::trained_run_folder(), html = learning_scratch("cut.html");
  fs::remove(html);
  for (const std::string value : {"0", "20001"}) {
    const auto refused = run_crux("report " + train.string() + " --replay-moves " + value + " -o " + html.string());
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_EQ(refused.err,
              "crux: --replay-moves: must be from 1 to 20000 (a move is about 4 KB of the page), got " + value + "\n");
    EXPECT_FALSE(fs::exists(html));
  }
  const auto whole = run_crux("report " + train.string() + " --climb last --json -o " + html.string());
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const int moves = nlohmann::json::parse(whole.out)["climb_moves"];
  ASSERT_GT(moves, 2);
  EXPECT_EQ(nlohmann::json::parse(whole.out)["replay_moves"], moves);
  EXPECT_EQ(read_text(html).find("<p class=\"cut\">"), std::string::npos);
  const auto json = run_crux("report " + train.string() + " --climb last --replay-moves 2 --json -o " + html.string());
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_EQ(nlohmann::json::parse(json.out)["replay_moves"], 2);
  EXPECT_EQ(nlohmann::json::parse(json.out)["climb_moves"], moves);
  EXPECT_NE(read_text(html).find(fmt::format(
                "<p class=\"cut\">This climb has {} moves; the replay shows its first 2 (crux report --replay-moves, "
                "at most 20000).</p>",
                moves)),
            std::string::npos);
  const auto text = run_crux("report " + train.string() + " --climb last --replay-moves 2 -o " + html.string());
  EXPECT_NE(
      text.out.find(fmt::format("a replay of {} with the first 2 of {} moves)", train.filename().string(), moves)),
      std::string::npos)
      << text.out;
}

// Issue 26: under the kinematic model a drawn posture may pass through the wall, and
// nothing said so. crux view says it for the posture it draws (text, SVG subtitle and
// --json), and crux report counts the climb's postures that do, with the deepest: the
// two agree posture by posture.
TEST(CliLearning, ViewAndReportSayWhenAPosturePassesThroughTheWall) {
  const fs::path train = testing::trained_run_folder();
  const fs::path svg = learning_scratch("in_wall.svg"), html = learning_scratch("in_wall.html");
  const auto report = run_crux("report " + train.string() + " --json -o " + html.string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const auto summary = nlohmann::json::parse(report.out);
  int in_wall = 0, postures = 0;
  double deepest = -1.0;
  for (int step = 0;; ++step) {
    const auto view =
        run_crux("view --run " + train.string() + " --step " + std::to_string(step) + " --json -o " + svg.string());
    if (view.exit_code != 0) break;
    ++postures;
    const auto penetration = nlohmann::json::parse(view.out)["wall_penetration"];
    const bool through = penetration["passes_through"];
    EXPECT_EQ(through, penetration["depth_m"].get<double>() > 0.01) << "step " << step;
    const std::string subtitle = nlohmann::json::parse(view.out)["subtitle"];
    EXPECT_EQ(subtitle.find(" m inside the wall (the kinematic model ignores the wall)") != std::string::npos, through)
        << subtitle;
    EXPECT_EQ(read_text(svg).find(" m inside the wall") != std::string::npos, through) << "step " << step;
    if (through) {
      ++in_wall;
      deepest = std::max(deepest, penetration["depth_m"].get<double>());
    }
  }
  ASSERT_GT(postures, 2);
  EXPECT_EQ(summary["postures_in_wall"], in_wall);
  ASSERT_GT(in_wall, 0) << "the trained run's greedy climb passes through the wall (measured: 16 of 17 postures)";
  EXPECT_DOUBLE_EQ(summary["deepest_in_wall_m"].get<double>(), deepest);
  EXPECT_NE(read_text(html).find(
                fmt::format("{} of the climb's {} recorded postures pass through the wall", in_wall, postures)),
            std::string::npos);
}

// -o naming a FIFO writes the page through it; a rename would have replaced the FIFO
// (and, run as root, -o /dev/null the machine's /dev/null) with a regular file.
TEST(CliLearning, AReportWrittenToAFifoGoesThroughItAndKeepsTheFifo) {
  const fs::path fifo = learning_scratch("report.fifo");
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  testing::FifoReader reader(fifo);
  ASSERT_TRUE(reader.opened());
  const auto report = run_crux("report " + testing::trained_run_folder().string() + " -o " + fifo.string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  EXPECT_EQ(reader.text().rfind("<!DOCTYPE html>", 0), 0u) << reader.text().substr(0, 100);
  EXPECT_TRUE(fs::is_fifo(fifo));
}

// A run is drawn and reported with its own config.toml: IK flags are refused with it,
// any episode can be replayed, and renamed flags name their new names.
TEST(CliLearning, ViewAndReportReadTheRunsOwnConfig) {
  const fs::path train = testing::trained_run_folder();
  const fs::path svg = learning_scratch("episode.svg"), html = learning_scratch("episode.html");
  const auto ik_flag = run_crux("view --run " + train.string() + " --ik-timeout 0.01 -o " + svg.string());
  EXPECT_EQ(ik_flag.exit_code, 2);
  EXPECT_EQ(ik_flag.err, "crux: --ik-timeout: not used with --run: a run is drawn with its own config.toml\n");
  const auto ik_config = testing::write_temporary("cli_view_ik.toml", "[ik]\ntimeout = 1.0\n");
  const auto from_file =
      run_crux("view --run " + train.string() + " --config " + ik_config.string() + " -o " + svg.string());
  EXPECT_EQ(from_file.err, "crux: " + ik_config.string() +
                               ": line 2: ik.timeout: not used with --run: a run is "
                               "drawn with its own config.toml\n");
  EXPECT_FALSE(fs::exists(svg));
  const auto report_ik = run_crux("report " + train.string() + " --ik-solver paper -o " + html.string());
  EXPECT_EQ(report_ik.exit_code, 2);
  EXPECT_NE(report_ik.err.find("unknown option --ik-solver of 'crux report'"), std::string::npos) << report_ik.err;

  const auto view = run_crux("view --run " + train.string() + " --climb 2 --step 1 --json -o " + svg.string());
  ASSERT_EQ(view.exit_code, 0) << view.err;
  EXPECT_NE(nlohmann::json::parse(view.out)["subtitle"].get<std::string>().find("of the climb of episode 2"),
            std::string::npos)
      << view.out;
  const auto report = run_crux("report " + train.string() + " --climb 2 --json -o " + html.string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const auto summary = nlohmann::json::parse(report.out);
  EXPECT_EQ(summary["replay_climb"], "episode");
  EXPECT_EQ(summary["replay_episode"], 2);
  EXPECT_EQ(summary["replay_reason"], "episode 2, as --climb 2 asks");
  // Episode 2 counts from 1, as Fig. 4 does: the second row of episodes.csv (its episode 1).
  std::ifstream episodes(train / "episodes.csv");
  std::string row;
  for (int line = 0; line < 3; ++line) std::getline(episodes, row);
  ASSERT_EQ(row.rfind("1,", 0), 0u) << row;
  EXPECT_EQ(summary["replay_moves"], std::stoi(row.substr(2)));
  const auto bad = run_crux("report " + train.string() + " --climb 100000 -o " + html.string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err.rfind("crux: --climb: the run has episodes 1 to ", 0), 0u) << bad.err;
  const auto zero = run_crux("view --run " + train.string() + " --climb 0 -o " + svg.string());
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_EQ(zero.err, "crux: --climb: episodes are numbered from 1, not 0\n");

  for (const auto& [old_name, command] :
       std::vector<std::pair<std::string, std::string>>{{"--svg", "view --svg x.svg"},
                                                        {"--replay-run", "report . --replay-run training_1 -o x.html"},
                                                        {"--queries", "ik-compare --queries 3"},
                                                        {"--walk-solver", "ik-compare --walk-solver fast"}}) {
    const auto renamed = run_crux(command);
    EXPECT_EQ(renamed.exit_code, 2) << command;
    EXPECT_NE(renamed.err.find("unknown option " + old_name + " of"), std::string::npos) << renamed.err;
    EXPECT_NE(renamed.err.find("(it is now --"), std::string::npos) << renamed.err;
  }
}

// crux figures draws a paper folder's figures again from its files, byte for byte.
TEST(CliLearning, FiguresRedrawsThePaperFiguresByteForByte) {
  const fs::path paper = learning_scratch("figures_paper");
  ASSERT_EQ(run_crux("paper --walls 2 --iterations 400 --plan false -o " + paper.string()).exit_code, 0);
  std::map<std::string, std::string> first;
  for (const auto& entry : fs::directory_iterator(paper / "figures")) {
    if (entry.path().extension() == ".svg") first[entry.path().filename().string()] = read_text(entry.path());
  }
  ASSERT_EQ(first.size(), 4u);
  for (const auto& [name, _] : first) fs::remove(paper / "figures" / name);
  const auto redrawn = run_crux("figures " + paper.string());
  ASSERT_EQ(redrawn.exit_code, 0) << redrawn.err;
  for (const auto& [name, svg] : first) EXPECT_EQ(read_text(paper / "figures" / name), svg) << name;
}

// Run folders that crux did not write, or wrote differently, are refused with one line
// and exit code 2, and nothing is written.
TEST(CliLearning, MalformedRunFoldersAreRefusedWithOneLine) {
  const fs::path train = learning_scratch("malformed_train");
  ASSERT_EQ(run_crux("train --wall-seed 3 --seed 5 --iterations 2000 -o " + train.string()).exit_code, 0);
  const auto copy_with = [&](const std::string& name, const std::string& file, const std::string& from,
                             const std::string& to) {
    const fs::path copy = learning_scratch(name);
    fs::copy(train, copy, fs::copy_options::recursive);
    std::string text = read_text(copy / file);
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    std::ofstream(copy / file, std::ios::trunc) << text;
    return copy;
  };
  // iterations.csv cut by `cut`.
  const auto copy_cut = [&](const std::string& name, const std::function<std::string(const std::string&)>& cut) {
    const fs::path copy = learning_scratch(name);
    fs::copy(train, copy, fs::copy_options::recursive);
    const std::string text = read_text(copy / "iterations.csv");
    std::ofstream(copy / "iterations.csv", std::ios::trunc) << cut(text);
    return copy;
  };
  const fs::path never = learning_scratch("malformed.svg");
  struct Case {
    fs::path folder;
    std::string problem;
  };
  const std::vector<Case> cases{
      {copy_with("far_posture", "climb.csv", "\n0,-0.2", "\n0,-9999.2"), "is outside [-1000, 1000] m"},
      {copy_with("negative_episode", "iterations.csv", "\n1,0,", "\n1,-1,"), "episodes count from 0"},
      {copy_with("unknown_regime", "iterations.csv", "\n1,0,random,", "\n1,0,randomly,"), "unknown regime"},
      {copy_cut("iterations_mid_row", [](const std::string& t) { return t.substr(0, t.size() - 5); }),
       "iterations.csv: does not end with a newline"},
      {copy_cut("iterations_no_newline", [](const std::string& t) { return t.substr(0, t.size() - 1); }),
       "iterations.csv: does not end with a newline"},
      {copy_cut("iterations_rows_removed", [](const std::string& t) { return t.substr(0, t.find("\n1999,") + 1); }),
       "iterations.csv: has 1998 iterations, but summary.json records 2000"}};
  for (const Case& c : cases) {
    for (const std::string& command : {"view --run " + c.folder.string() + " -o " + never.string(),
                                       "report " + c.folder.string() + " -o " + never.string()}) {
      const auto outcome = run_crux(command);
      EXPECT_EQ(outcome.exit_code, 2) << command;
      EXPECT_EQ(testing::count_lines(outcome.err), 1) << outcome.err;
      EXPECT_NE(outcome.err.find(c.problem), std::string::npos) << outcome.err;
    }
  }
  EXPECT_FALSE(fs::exists(never));
  const auto not_paper = run_crux("figures " + train.string());
  EXPECT_EQ(not_paper.exit_code, 2);
  EXPECT_NE(not_paper.err.find("not a crux paper folder"), std::string::npos) << not_paper.err;
  EXPECT_FALSE(fs::exists(train / "figures"));
}

TEST(CliLearning, EveryCommandPrintsOneJsonDocument) {
  const fs::path wall = learning_scratch("json_wall.json"), train = learning_scratch("json_train");
  const std::vector<std::string> commands{
      "model",
      "demo",
      "ik --rh 0.3,1.5 --lh 0.9,1.5 --rf 0.3,0 --lf 0.9,0",
      "ik-compare --compare-queries 5",
      "wall generate --wall-seed 5 -o " + wall.string(),
      "wall show --wall-file " + wall.string(),
      "filter-stats --wall-count 1",
      "plan --wall-file " + wall.string(),
      "train --wall-file " + wall.string() + " --iterations 100 -o " + train.string(),
      "transfer --q-grid " + (train / "q_grid.bin").string() + " --wall-seed 2 --iterations 100 -o " +
          learning_scratch("json_transfer").string(),
      "paper --walls 1 --iterations 100 --plan false -o " + learning_scratch("json_paper").string(),
      "view --wall-file " + wall.string() + " -o " + learning_scratch("json_view.svg").string(),
      "figures " + learning_scratch("json_paper").string(),
      "report " + learning_scratch("json_paper").string() + " -o " + learning_scratch("json_report.html").string(),
      "report " + train.string() + " -o " + learning_scratch("json_train_report.html").string()};
  for (const std::string& command : commands) {
    const auto outcome = run_crux(command + " --json");
    ASSERT_EQ(outcome.exit_code, 0) << command << ": " << outcome.err;
    EXPECT_TRUE(nlohmann::json::accept(outcome.out)) << command << ": " << outcome.out;
  }
}

// crux train killed after a checkpoint and started again with the same command ends
// with the files of a run never stopped; another run's parameters refuse the checkpoint.
TEST(CliLearning, ALongRunKilledResumesFromItsCheckpointToTheSameBytes) {
  const std::string arguments = "train --wall-seed 3 --seed 5 --iterations 6000 --checkpoint-every 500 -o ";
  const fs::path whole = learning_scratch("long-whole"), killed = learning_scratch("long-killed");
  ASSERT_EQ(run_crux(arguments + whole.string()).exit_code, 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const std::string command =
        std::string("exec ") + CRUX_BINARY + " " + arguments + killed.string() + " > " + killed.string() + ".log 2>&1";
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(killed / "checkpoint.bin") && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it was killed";
  ASSERT_TRUE(fs::exists(killed / "checkpoint.bin"))
      << "written before the INCOMPLETE marker, which may not be there yet";
  const auto other = run_crux(arguments + killed.string() + " --learning-epsilon 0.2");
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("checkpoint.bin: is the checkpoint of another run"), std::string::npos) << other.err;
  // As a kill while the final files were written, or while a checkpoint was, leaves it.
  std::ofstream(killed / "config.toml") << "half";
  std::ofstream(killed / "checkpoint.bin.tmp.0123456789abcdef") << "half";
  const auto resumed = run_crux(arguments + killed.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("crux train: resumed at iteration "), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find(" of 6000 from " + (killed / "checkpoint.bin").string()), std::string::npos)
      << resumed.err;
  EXPECT_FALSE(fs::exists(killed / "checkpoint.bin")) << "a complete folder keeps no checkpoint";
  EXPECT_FALSE(fs::exists(killed / "INCOMPLETE"));
  for (const char* file :
       {"iterations.csv", "episodes.csv", "q_grid.bin", "climb.csv", "greedy_climb.csv", "wall.json", "config.toml"}) {
    std::ifstream a(whole / file, std::ios::binary), b(killed / file, std::ios::binary);
    const std::string x((std::istreambuf_iterator<char>(a)), {}), y((std::istreambuf_iterator<char>(b)), {});
    EXPECT_TRUE(!x.empty() && x == y) << file;
  }
  EXPECT_FALSE(fs::exists(killed / "checkpoint.bin.tmp.0123456789abcdef"));
  // A folder killed while it wrote its first checkpoint holds temporaries only: it starts afresh.
  const fs::path first = learning_scratch("long-first");
  fs::create_directories(first);
  std::ofstream(first / "INCOMPLETE.tmp.fedcba9876543210") << "half";
  const auto afresh = run_crux(arguments + first.string());
  EXPECT_EQ(afresh.exit_code, 0) << afresh.err;
}

// The job refuses a transfer without its Q_grid before it loads anything, and the
// command names the flag.
TEST(CliLearning, ATransferWithoutAQGridNamesTheFlag) {
  const fs::path out = learning_scratch("transfer_without_q_grid");
  const auto outcome = run_crux("transfer --wall-seed 3 --iterations 100 -o " + out.string());
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_EQ(outcome.err, "crux: --q-grid: give the Q_grid to transfer (q_grid.bin of a training run)\n");
  EXPECT_FALSE(fs::exists(out));
}

// A wall file gives the wall, so a random wall's parameters beside it are refused (they
// were once ignored and recorded), and config.toml records none of them.
TEST(CliLearning, WallGeneratorFlagsBesideAWallFileAreRefused) {
  const fs::path wall = learning_scratch("generator_wall.json"), out = learning_scratch("generator_out");
  ASSERT_EQ(run_crux("wall generate --wall-seed 5 -o " + wall.string()).exit_code, 0);
  for (const char* flag : {"--wall-sigma 0.2", "--wall-rows 9", "--wall-finish-height 2.5"}) {
    const auto refused =
        run_crux("train --wall-file " + wall.string() + " " + flag + " --iterations 100 -o " + out.string());
    EXPECT_EQ(refused.exit_code, 2) << flag;
    EXPECT_EQ(refused.err.rfind("crux: " + std::string(flag).substr(0, std::string(flag).find(' ')) +
                                    ": shapes a "
                                    "random wall, and the wall file gives the wall itself: drop one of them\n",
                                0),
              0u)
        << refused.err;
    EXPECT_FALSE(fs::exists(out)) << flag;
  }
  ASSERT_EQ(run_crux("train --wall-file " + wall.string() + " --iterations 100 -o " + out.string()).exit_code, 0);
  std::ifstream in(out / "config.toml");
  const std::string config((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(config.find("[wall]\nfile = "), std::string::npos) << config;
  EXPECT_EQ(config.find("sigma"), std::string::npos) << config;
  EXPECT_EQ(config.find("finish_height"), std::string::npos) << config;
  // The folder's own config replays it.
  EXPECT_EQ(run_crux("train --config " + (out / "config.toml").string() + " -o " +
                     learning_scratch("generator_again").string())
                .exit_code,
            0);
  // A random wall's config.toml lists its parameters; a wall file given as a flag
  // replaces that wall, parameters and all.
  const fs::path seeded = learning_scratch("generator_seeded");
  ASSERT_EQ(run_crux("train --wall-seed 3 --iterations 100 -o " + seeded.string()).exit_code, 0);
  const auto replaced = run_crux("train --config " + (seeded / "config.toml").string() + " --wall-file " +
                                 wall.string() + " -o " + learning_scratch("generator_replaced").string());
  EXPECT_EQ(replaced.exit_code, 0) << replaced.err;
}

TEST(CliLearning, TheTransferModeIsOneFlagWrittenToTheConfigAndAnUnknownOneIsRefused) {
  const fs::path train = learning_scratch("mode_train"), transfer = learning_scratch("mode_transfer"),
                 again = learning_scratch("mode_again");
  ASSERT_EQ(run_crux("train --wall-seed 3 --iterations 200 --transfer prior -o " + train.string()).exit_code, 0);
  EXPECT_NE(read_text(train / "config.toml").find("transfer = \"prior\""), std::string::npos);
  ASSERT_EQ(run_crux("transfer --q-grid " + (train / "q_grid.bin").string() +
                     " --wall-seed 4 --iterations 200 --transfer seeded -o " + transfer.string())
                .exit_code,
            0);
  const auto replayed = run_crux("transfer --config " + (transfer / "config.toml").string() + " -o " + again.string());
  ASSERT_EQ(replayed.exit_code, 0) << replayed.err;
  expect_same_folder(transfer, again);
  const auto unknown = run_crux("transfer --q-grid " + (train / "q_grid.bin").string() +
                                " --wall-seed 4 --transfer best -o " + learning_scratch("mode_unknown").string());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--transfer"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("unknown transfer 'best'"), std::string::npos) << unknown.err;
  EXPECT_EQ(testing::count_lines(unknown.err), 1) << unknown.err;
  EXPECT_FALSE(fs::exists(learning_scratch("mode_unknown")));
}

// With an empty Q_grid the shaping potential is 0 everywhere, so the shaping mode's
// training and control runs are the paper's, iteration by iteration, while transfer
// differs.
TEST(CliLearning, ShapingWithoutATransferredTableIsThePaperRule) {
  const fs::path paper = learning_scratch("mode_paper"), shaping = learning_scratch("mode_shaping");
  const std::string common = "paper --walls 1 --seeds-per-wall 2 --iterations 2000 --plan false --seed 3 ";
  ASSERT_EQ(run_crux(common + "-o " + paper.string()).exit_code, 0);
  ASSERT_EQ(run_crux(common + "--transfer shaping -o " + shaping.string()).exit_code, 0);
  for (const char* run : {"training_0", "training_1", "control_0", "control_1"}) {
    EXPECT_EQ(read_text(paper / "runs" / run / "iterations.csv"), read_text(shaping / "runs" / run / "iterations.csv"))
        << run;
  }
  EXPECT_TRUE(
      read_text(paper / "runs/transfer_0/iterations.csv") + read_text(paper / "runs/transfer_1/iterations.csv") !=
      read_text(shaping / "runs/transfer_0/iterations.csv") + read_text(shaping / "runs/transfer_1/iterations.csv"))
      << "the transferred potential changes transfer's runs";
}

// Without a transferred table the ordered rule is epsilon-greedy on Q_wall, the seeded
// rule without seeds: training and control are seeded's, iteration by iteration, while
// transfer differs.
TEST(CliLearning, OrderedWithoutATransferredTableIsTheSeededRuleWithoutSeeds) {
  const fs::path seeded = learning_scratch("mode_seeded"), ordered = learning_scratch("mode_ordered");
  const std::string common = "paper --walls 1 --seeds-per-wall 2 --iterations 2000 --plan false --seed 3 ";
  ASSERT_EQ(run_crux(common + "--transfer seeded -o " + seeded.string()).exit_code, 0);
  ASSERT_EQ(run_crux(common + "--transfer ordered -o " + ordered.string()).exit_code, 0);
  for (const char* run : {"training_0", "training_1", "control_0", "control_1"}) {
    EXPECT_EQ(read_text(seeded / "runs" / run / "iterations.csv"), read_text(ordered / "runs" / run / "iterations.csv"))
        << run;
  }
  EXPECT_TRUE(
      read_text(seeded / "runs/transfer_0/iterations.csv") + read_text(seeded / "runs/transfer_1/iterations.csv") !=
      read_text(ordered / "runs/transfer_0/iterations.csv") + read_text(ordered / "runs/transfer_1/iterations.csv"))
      << "the transferred order changes transfer's runs";
}

}  // namespace
}  // namespace crux
